"""Shared harness of the thorns' whole-run tests (thorns/*/test/test_runs.py): command-line
arguments, a fresh work folder, runs of the remnant executable under mpirun with their output
logged, and dispatch to the named test mode.

    import remnant_runs
    def mode_x(r): out, p = r.run("name", 2, ["MoL::max_iterations=4"])
    remnant_runs.main(lambda a: remnant_runs.Runner(a, parfile, base_args), {"x": mode_x})
"""
import argparse
import os
import shutil
import subprocess
import sys


class Runner:
    """Runs `exe parfile Flesh::out_dir=<work>/<name> base_args args` under mpirun; the command and
    its output are appended to <work>/<name>.log."""

    def __init__(self, a, parfile, base_args):
        self.a = a
        self.parfile = parfile
        self.base_args = list(base_args)

    def run(self, name, np_, args, expect_ok=True):
        out = os.path.join(self.a.work, name)
        cmd = [self.a.mpirun, "-np", str(np_), "--oversubscribe", self.a.exe, self.parfile,
               "Flesh::out_dir=" + out] + self.base_args + list(args)
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        with open(os.path.join(self.a.work, name + ".log"), "a") as f:
            f.write(" ".join(cmd) + "\n" + p.stdout)
        if expect_ok and p.returncode != 0:
            sys.exit("run %s failed (rc %d):\n%s" % (name, p.returncode, p.stdout[-4000:]))
        return out, p


def main(make_runner, modes):
    """Parses --mode/--exe/--mpirun/--source-dir/--work, empties the work folder and runs the mode
    with the Runner that make_runner(args) returns."""
    ap = argparse.ArgumentParser()
    ap.add_argument("--mode", required=True)
    ap.add_argument("--exe", required=True)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--source-dir", required=True)
    ap.add_argument("--work", required=True)
    a = ap.parse_args()
    if a.mode not in modes:
        sys.exit("unknown mode %s; modes: %s" % (a.mode, ", ".join(modes)))
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    modes[a.mode](make_runner(a))
