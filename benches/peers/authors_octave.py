#!/usr/bin/env python3
"""The authors' own simulation (toshankarghosh/toothpicks, main_rod.m) as a peer.

Runs the authors' MATLAB code under GNU Octave on a temporary copy of their checkout,
reads its phase log, runs the workbook on the same scene (`--scene authors`, g = 10 m/s^2)
from the same starting state with `--events`, and prints the transition-by-transition
comparison. Python 3 standard library only. Not part of `cargo test`.

What is changed in the temporary copy (never in the checkout, never committed):
  * `plotData_phase_paper(D, D1, setup)` at the end of main_rod.m is replaced by
    `peer_phase_log(D, D1)` (benches/peers/peer_phase_log.m, headless: one PEERLOG line
    per phase with its end time, phase, exit code, theta, theta', x_c at its end);
  * `deval.m` (benches/peers/deval.m) is added: Octave 7 has none; linear interpolation
    of the accepted points, exact at the phase ends, which is all fsm.m reads;
  * `num2str(sol.ie)` in the simulate_*.m progress messages becomes
    `num2str(sol.ie(:).')`: when two events fire in one step sol.ie is a column and the
    message's horizontal concatenation fails (display only);
  * unless --stock: `'InitialStep', 1e-12` is added to the four odeset calls. Octave's
    ode45 ignores a terminal event found in an integration's first step (its
    ode_event_handler.m, the "Matlab compatibility" comment); a 1e-12 s first step makes
    the event that is due at once fall in the second step, where it stops the run;
  * with --start static: setup.IC is set to the workbook's static start (theta = the
    static angle theta_f_exp = 0.5 rad, C on the plate at rest, P at rest: the plate's
    velocity at t = 0 is zero), instead of main_rod.m's theta = theta_0 and
    dyp = yc = A (metres used as m/s, about 2.8 mm/s).
  * with --max-step-s H (an experiment): 'MaxStep', H in the four odeset calls;
  * tfinal = --duration-s (default 1 s, main_rod.m's own).

Exit status: 0 when it ran (the comparison is information) or was skipped (Octave or the
checkout missing, said on stderr); 1 on a tool error (Octave failed, no log, the workbook
failed); 2 on a bad flag value (one line on stderr naming the flag, value and range).

Usage:
  python3 benches/peers/authors_octave.py [CHECKOUT] [--stock] [--start authors-code|static]
  python3 benches/peers/authors_octave.py [CHECKOUT] --all      # the three forms
CHECKOUT is a work tree of the authors' repository or a bare git directory (read with
`git archive HEAD`); default: the environment variable TOOTHPICKS_DIR.
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

# Switches at or before this time (s) choose the first mode (see one_form): a first phase
# this short is a few InitialSteps (1e-12 s) and an event search, four orders below the
# shortest physical phase of these runs (about 1e-5 s).
T_START_S = 1e-9
HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent

# Their names -> the workbook's. HINGE is the pivot (C fixed on the plate). SLIDE_POS
# integrates with xdot_c >= 0 (Event_SlidePos's event 3 is xdot_c falling to 0, 'STUCK'),
# and the workbook's x axis points the same way (both put P at x_c + L sin(theta)), so
# SLIDE_POS is slide_right; checked on the data: the modes agree at every matched switch.
PHASES = {
    "HINGE": "pivot",
    "FLIGHT": "flight",
    "SLIDE_POS": "slide_right",
    "SLIDE_NEG": "slide_left",
}
ODESET = re.compile(r"odeset\(")
PLOT_CALL = re.compile(r"^\s*plotData_phase_paper\(D, D1, setup\)\s*$", re.M)
TFINAL = re.compile(r"^(\s*tfinal\s*=\s*)1;", re.M)
TSPAN = re.compile(r"^setup\.Tspan\s*=", re.M)
STATIC_IC = """% --- workbook peer runner: start from the workbook's static state ---
setup.IC.th  = setup.p.theta_f_exp;   % the static angle, 0.5 rad
setup.IC.dth = 0;
setup.IC.xc  = 0;  setup.IC.yc  = (setup.p.A) * cos(setup.p.omega * tstart);
setup.IC.dxc = 0;  setup.IC.dyc = 0;  % the plate's velocity at t = 0 is zero
setup.IC.dxp = 0;  setup.IC.dyp = 0;  % P at rest too (main_rod.m: dyp = yc)
setup.IC.xp  = setup.IC.xc + setup.p.l * sin(setup.IC.th);
setup.IC.yp  = setup.IC.yc + setup.p.l * cos(setup.IC.th);
% --- end of the runner's change ---
"""


class ToolError(Exception):
    """A failure of the tools (not a disagreement of the simulations)."""


def skip(msg):
    print(f"authors_octave: skipped: {msg}", file=sys.stderr)
    sys.exit(0)


def copy_checkout(src, dst):
    """Copy a work tree, or extract HEAD of a bare git directory, into dst."""
    if (src / "main_rod.m").is_file():
        shutil.copytree(src, dst, dirs_exist_ok=True, ignore=shutil.ignore_patterns(".git"))
        return
    git = shutil.which("git")
    if git is None:
        skip(f"{src} has no main_rod.m and git is not installed to read it as a repository")
    arch = subprocess.run([git, f"--git-dir={src}", "archive", "HEAD"], capture_output=True)
    if arch.returncode != 0:
        skip(f"{src} is neither a checkout with main_rod.m nor a git repository")
    subprocess.run(["tar", "-x", "-C", str(dst)], input=arch.stdout, check=True)
    if not (dst / "main_rod.m").is_file():
        skip(f"{src} (git HEAD) has no main_rod.m: not the authors' repository")


def patch(work, stock, start, duration_s, max_step_s=None):
    """Apply the runner's changes (module docstring) to the temporary copy."""
    for name in ("deval.m", "peer_phase_log.m"):
        shutil.copy(HERE / name, work / name)
    n_odeset = 0
    for f in sorted(work.glob("simulate_*.m")):
        text = f.read_text()
        text = text.replace("num2str(sol.ie)", "num2str(sol.ie(:).')")
        extra = "" if stock else "'InitialStep', 1e-12, "
        if max_step_s is not None:
            extra += f"'MaxStep', {max_step_s!r}, "
        text, n = ODESET.subn(f"odeset({extra}", text)
        n_odeset += n
        f.write_text(text)
    if n_odeset != 4:
        raise ToolError(f"expected 4 odeset calls in simulate_*.m, found {n_odeset}")
    main = (work / "main_rod.m").read_text()
    main, n = PLOT_CALL.subn("peer_phase_log(D, D1)", main)
    if n != 1:
        raise ToolError("main_rod.m: the plotData_phase_paper call was not found")
    main, n = TFINAL.subn(rf"\g<1>{duration_s!r};", main)
    if n != 1:
        raise ToolError("main_rod.m: the line 'tfinal = 1;' was not found")
    if start == "static":
        m = TSPAN.search(main)
        if m is None:
            raise ToolError("main_rod.m: the line 'setup.Tspan = ...' was not found")
        main = main[: m.start()] + STATIC_IC + main[m.start():]
    (work / "main_rod.m").write_text(main)


def run_octave(work, timeout_s):
    """Run main_rod.m; returns the phase log [(t, phase, exit, theta, theta', x_c)]."""
    cmd = ["octave", "--no-gui", "--quiet", "--no-window-system", "--eval", "main_rod"]
    try:
        res = subprocess.run(cmd, cwd=work, capture_output=True, text=True, timeout=timeout_s)
    except subprocess.TimeoutExpired:
        raise ToolError(f"octave did not finish within --timeout-s {timeout_s}")
    log = []
    for line in res.stdout.splitlines():
        if line.startswith("PEERLOG "):
            f = line.split()
            log.append((float(f[2]), f[3], f[4], float(f[5]), float(f[6]), float(f[7])))
    if res.returncode != 0 or not log:
        tail = "\n".join(res.stderr.splitlines()[-15:])
        raise ToolError(f"octave exited with {res.returncode}, {len(log)} log lines:\n{tail}")
    return log


def their_transitions(log):
    """Phase i ends at log[i].t and hands over to phase i+1 (or ABORT / the end)."""
    out = []
    for i, (t, ph, code, th, om, xc) in enumerate(log):
        if i + 1 < len(log):
            to = PHASES.get(log[i + 1][1], log[i + 1][1])
        elif code == "TIMEOUT":
            break  # the run reached tfinal
        else:
            to = "ABORT"
        out.append({"t": t, "from": PHASES.get(ph, ph), "to": to, "code": code,
                    "theta": th, "x_c": xc})
    return out


def workbook_cmd():
    target = Path(os.environ.get("CARGO_TARGET_DIR", REPO / "target"))
    exe = target / "release" / "workbook"
    if exe.is_file():
        return [str(exe)]
    return ["cargo", "run", "--release", "--quiet", "--"]


def run_workbook(start, duration_s, tmp):
    """The workbook's switches (from --events) and its x_C at the end (m)."""
    import json

    csv_path = tmp / "workbook_events.csv"
    cmd = workbook_cmd() + [
        "stick-state-machine", "--scene", "authors", "--start", start,
        "--duration-s", str(duration_s), "--events", str(csv_path), "--no-figures", "--json",
    ]
    res = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True)
    if res.returncode != 0:
        raise ToolError(f"workbook failed ({' '.join(cmd)}):\n{res.stderr.strip()}")
    with open(csv_path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    events = [{"t": float(r["t_s"]), "from": r["from"], "to": r["to"],
               "theta": float(r["theta_rad"]), "x_c": float(r["x_c_m"])} for r in rows]
    results = json.loads(res.stdout)["results"]
    # x_C(0) = 0: mean_velocity_mps = (x_C(end) - x_C(0)) / (end - 0), rounded to 1e-6
    x_end = results["mean_velocity_mps"] * results["end_time_s"]
    return events, x_end


def compare(theirs, ours, x_theirs, x_ours, label):
    print(f"\n== {label}")
    print(f"{'i':>3} {'t theirs (s)':>16} {'t ours (s)':>16} {'dt (s)':>10}  "
          f"{'theirs':<24} {'ours':<24} {'dtheta (rad)':>12}")
    matched, max_dt, first_diff = 0, 0.0, None
    for i in range(max(len(theirs), len(ours))):
        a = theirs[i] if i < len(theirs) else None
        b = ours[i] if i < len(ours) else None
        ta = f"{a['t']:16.9f}" if a else f"{'-':>16}"
        tb = f"{b['t']:16.9f}" if b else f"{'-':>16}"
        ma = f"{a['from']}->{a['to']}" if a else "-"
        mb = f"{b['from']}->{b['to']}" if b else "-"
        if a and b:
            dt = a["t"] - b["t"]
            same = (a["from"], a["to"]) == (b["from"], b["to"])
            flag = "" if same else "  <- modes differ"
            print(f"{i + 1:>3} {ta} {tb} {dt:10.2e}  {ma:<24} {mb:<24} "
                  f"{a['theta'] - b['theta']:12.2e}{flag}")
            if same and first_diff is None:
                matched += 1
                max_dt = max(max_dt, abs(dt))
            elif first_diff is None:
                first_diff = i + 1
        else:
            print(f"{i + 1:>3} {ta} {tb} {'':>10}  {ma:<24} {mb:<24}")
            if first_diff is None:
                first_diff = i + 1
    print(f"summary ({label}): transitions theirs {len(theirs)}, ours {len(ours)}; "
          f"the first {matched} match in modes, max |dt| over them {max_dt:.2e} s"
          + (f"; first difference at #{first_diff}" if first_diff else ""))
    end_a = theirs[-1]["to"] if theirs and theirs[-1]["to"] == "ABORT" else "ran to the end"
    print(f"summary ({label}): x_C at the end: theirs {x_theirs:.6f} m ({end_a}), "
          f"ours {x_ours:.6f} m")


def one_form(src, stock, start, duration_s, timeout_s, max_step_s=None):
    label = f"{'stock Octave' if stock else 'InitialStep 1e-12'}, start {start}"
    if max_step_s is not None:
        label += f", MaxStep {max_step_s:g} s"
    with tempfile.TemporaryDirectory(prefix="toothpicks-") as tmp:
        tmp = Path(tmp)
        work = tmp / "toothpicks"
        work.mkdir()
        copy_checkout(src, work)
        patch(work, stock, start, duration_s, max_step_s)
        log = run_octave(work, timeout_s)
        ours, x_ours = run_workbook(start, duration_s, tmp)
    theirs = their_transitions(log)
    # A switch at t = 0 is the choice of the first mode, not an event of the run: from
    # the static start selectPhase finds F_z < 0 in the pivot (the plate accelerates
    # down at 10 g) and starts in FLIGHT, whose landing event fires at once (a zero-length
    # flight, then the slide); the workbook starts in that slide. Set such switches apart.
    for name, lst in (("theirs", theirs), ("ours", ours)):
        for ev in [e for e in lst if e["t"] <= T_START_S]:
            print(f"note ({label}): {name} switch at t = {ev['t']:.3g} s, "
                  f"{ev['from']} -> {ev['to']}: the choice of the first mode, not compared")
    theirs = [e for e in theirs if e["t"] > T_START_S]
    ours = [e for e in ours if e["t"] > T_START_S]
    compare(theirs, ours, log[-1][5], x_ours, label)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("checkout", nargs="?", default=os.environ.get("TOOTHPICKS_DIR"),
                    help="the authors' repository: a work tree or a bare git directory "
                         "(default: $TOOTHPICKS_DIR)")
    ap.add_argument("--stock", action="store_true",
                    help="without the InitialStep fix (Octave's own first-step semantics)")
    ap.add_argument("--start", choices=["authors-code", "static"], default="authors-code",
                    help="main_rod.m's initial state (default) or the workbook's static one")
    ap.add_argument("--all", action="store_true",
                    help="the three forms: stock/authors-code, fix/authors-code, fix/static")
    ap.add_argument("--duration-s", type=float, default=1.0,
                    help="simulated time (s), both sides (default 1, main_rod.m's tfinal)")
    ap.add_argument("--timeout-s", type=float, default=1800.0,
                    help="wall-time limit of each Octave run (s) (default 1800)")
    ap.add_argument("--max-step-s", type=float, default=None,
                    help="an experiment: ode45's MaxStep (s) in all four phases. Octave "
                         "locates an event by one secant across the step that brackets it "
                         "(ode_event_handler.m), an error that shrinks with the step")
    args = ap.parse_args()
    if not 1.0 <= args.timeout_s <= 86400.0:
        print(f"--timeout-s {args.timeout_s}: must be in [1, 86400] s", file=sys.stderr)
        sys.exit(2)
    if args.max_step_s is not None and not 1e-7 <= args.max_step_s <= 1.0:
        print(f"--max-step-s {args.max_step_s}: must be in [1e-7, 1] s", file=sys.stderr)
        sys.exit(2)
    if not (args.duration_s > 0 and args.duration_s <= 100):
        print(f"--duration-s {args.duration_s}: must be in (0, 100] s", file=sys.stderr)
        sys.exit(2)
    if shutil.which("octave") is None:
        skip("GNU Octave is not installed (octave not on PATH)")
    if not args.checkout:
        skip("no checkout of toshankarghosh/toothpicks given (argument or TOOTHPICKS_DIR)")
    src = Path(args.checkout)
    if not src.is_dir():
        skip(f"the checkout {src} does not exist")
    forms = ([(True, "authors-code"), (False, "authors-code"), (False, "static")]
             if args.all else [(args.stock, args.start)])
    try:
        for stock, start in forms:
            one_form(src, stock, start, args.duration_s, args.timeout_s, args.max_step_s)
    except ToolError as e:
        print(f"authors_octave: error: {e}", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
