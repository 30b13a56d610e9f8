#!/usr/bin/env python3
"""bench/remnant_run.py, shared by the benchmark scripts: the run's command line (plain, under
mpirun, behind a wrapper), the timer table, and that neither script keeps a copy of them."""
import os
import sys

BENCH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "bench")
sys.path.insert(0, BENCH)
import remnant_run  # noqa: E402

TABLE = """
Timers (seconds):
  function                         calls      total    percent
  MoL::MoL_Step                       30      0.600      40.00
  XCFC::XCFC_Solve                    31      0.450      30.00
  XCFC::XCFC_VectorPotential          31      0.125       8.33
Timers again:
  MoL::MoL_Step                       99      9.000      90.00
"""


def main():
    t = remnant_run.timers(TABLE)
    assert t["MoL::MoL_Step"] == (30, 0.6), t  # the first table wins
    assert t["XCFC::XCFC_Solve"] == (31, 0.45), t
    assert len(t) == 3, t
    assert remnant_run.command("exe", "p.yaml", ["A::b=1"], "out") == ["exe", "p.yaml", "A::b=1", "Flesh::out_dir=out"]
    cmd = remnant_run.command("exe", "p.yaml", [], "out", np=2, mpirun="mr", wrapper=["vg", "--x"])
    assert cmd == ["mr", "-np", "2", "--oversubscribe", "vg", "--x", "exe", "p.yaml", "Flesh::out_dir=out"], cmd
    for script in ("solve_cost.py", "rank_instructions.py"):
        text = open(os.path.join(BENCH, script)).read()
        assert "from remnant_run import" in text, f"{script} does not use bench/remnant_run.py"
        assert "re.compile(r\"^\\s+(\\S+::\\S+)" not in text and "subprocess.run(cmd, capture_output=True, text=True)\n    if" not in text, \
            f"{script} keeps its own copy of the run or timer-table code"
    print("bench/remnant_run.py: command lines, timer table, shared by solve_cost.py and rank_instructions.py")


if __name__ == "__main__":
    main()
