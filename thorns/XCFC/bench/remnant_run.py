"""What the XCFC benchmark scripts share (solve_cost.py, rank_instructions.py): the command line of a
run of `remnant` (optionally under mpirun and a wrapper such as valgrind), running it with a clear
error when it fails, and the timer table it prints at the end."""
import re
import subprocess
import sys

# One row of the timer table: "  Thorn::Function  calls  seconds  percent".
TIMER_ROW = re.compile(r"^\s+(\S+::\S+)\s+(\d+)\s+([0-9.]+)\s+([0-9.]+)\s*$")


def command(exe, parfile, overrides, out_dir, np=1, mpirun="mpirun", wrapper=()):
    """remnant PARFILE OVERRIDES... Flesh::out_dir=OUT_DIR, behind `wrapper` (e.g. valgrind and its
    options) and, for np > 1, `mpirun -np NP --oversubscribe`."""
    cmd = [*wrapper, exe, parfile, *overrides, f"Flesh::out_dir={out_dir}"]
    if np > 1:
        cmd = [mpirun, "-np", str(np), "--oversubscribe", *cmd]
    return cmd


def run_or_exit(cmd, tool):
    """Runs cmd; on a non-zero exit prints the ends of its output and exits naming `tool`."""
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-4000:] + r.stderr[-4000:])
        sys.exit(f"{tool}: the run failed (exit {r.returncode}): {' '.join(cmd)}")
    return r


def timers(text):
    """{function: (calls, seconds)} from the timer table at the end of a run (first table printed)."""
    out = {}
    for line in text.splitlines():
        m = TIMER_ROW.match(line)
        if m and m.group(1) not in out:
            out[m.group(1)] = (int(m.group(2)), float(m.group(3)))
    return out
