#!/usr/bin/env python3
"""cardillo's Painleve example against the workbook's rod with inertia (chapter 8).

cardillo (github cardilloproject/cardillo, nonsmooth multibody dynamics in Python) had
an example `examples/nonsmooth/painleve.py` (earlier `examples/Painleve.py`): Glocker's
"impact without collision" (Glocker 1995, 5.3.4), a uniform rod of half-length s = 1 m,
m = 1 kg, J = m s^2 / 3, g = 10, mu = 5/3, leaning 31 deg from the floor, its lower end
sliding at 30 m/s away from the top. The example was removed from the repository in
commit 8d905784 (2024-03-26); this runner takes it and the package from its last commit,
1bcc3377 (2024-02-29), into a temporary directory (nothing of cardillo is kept here),
and runs the example's class `Painleve_rod` with cardillo's own solvers `Moreau` and
`BackwardEuler` at a ladder of time steps (the example itself uses dt = 5e-3 s for both,
to t = 1.5 s, and draws a marker at t_a = 0.83 s). For each run it prints the step with
the largest normal impulse (the impact without collision), the centre's velocity and
the rate before and after it, and the state at t = 1.085 s.

The workbook side: `target/release/examples/peer_runs painleve` (the same scene in
chapter 8's model, DOP853 rtol 1e-10, events located; the rule for the inconsistent
slide is the impact without collision integrated in the normal impulse).

Needs: a cardillo checkout (git work tree or bare git dir; CARDILLO_DIR or --cardillo),
and a Python with numpy < 2 and scipy 1.12 for cardillo of that date (--python; newer
scipy fails in `estimate_prox_parameter`), plus matplotlib, tqdm, dill, cachetools,
trimesh, meshio (it imports them). Without them it says so on stderr and exits 0.
Run: python3 benches/peers/cardillo_painleve.py --help
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

COMMIT = "1bcc3377"  # the last commit with examples/nonsmooth/painleve.py
EXAMPLE = "examples/nonsmooth/painleve.py"
T_COMPARE = 1.085  # the workbook's run ends there: the rod turns flat in flight ("fell")
G = 10.0

CHILD = r"""
import importlib.util, json, sys, time
import numpy as np
import matplotlib
matplotlib.use("Agg")
root, solver, dt, t_cmp = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
SAMPLES = json.loads(sys.argv[5])
sys.path.insert(0, root)
spec = importlib.util.spec_from_file_location("painleve", root + "/examples/nonsmooth/painleve.py")
ex = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ex)  # the example's class only: its __main__ block is not run
from cardillo import System
from cardillo.solver import Moreau, BackwardEuler, SolverOptions
system = System()
system.add(ex.Painleve_rod())
system.assemble()
opts = SolverOptions(fixed_point_max_iter=int(1e5))
cls = {"moreau": Moreau, "backward-euler": BackwardEuler}[solver]
t0 = time.perf_counter()
sol = cls(system, 1.5, dt, options=opts).solve()
wall = time.perf_counter() - t0
i = int(np.argmax(sol.P_N[:, 0]))
j = int(np.argmin(np.abs(sol.t - t_cmp)))
last = max([k for k in range(i) if sol.P_N[k, 0] > 0], default=-1)  # the last step in contact before it
samples = [[float(sol.t[k]), sol.q[k].tolist(), sol.u[k].tolist()]
           for k in (int(np.argmin(np.abs(sol.t - ts))) for ts in SAMPLES)]
print(json.dumps({"solver": solver, "dt_s": dt, "wall_s": wall, "impact_step_t_s": float(sol.t[i]),
    "u_before": sol.u[i - 1].tolist(), "u_after": sol.u[i].tolist(),
    "P_N_before": float(sol.P_N[i - 1, 0]), "P_N": float(sol.P_N[i, 0]), "P_F": float(sol.P_F[i, 0]),
    "last_contact_t_s": float(sol.t[last]), "samples": samples,
    "t_cmp_s": float(sol.t[j]), "q_cmp": sol.q[j].tolist(), "u_cmp": sol.u[j].tolist()}))
"""


def cardillo_tree(src, tmp):
    """Extracts the package and the example at COMMIT into tmp; None when impossible."""
    git_dir = src if os.path.isfile(os.path.join(src, "HEAD")) else os.path.join(src, ".git")
    if os.path.isdir(git_dir) or os.path.isfile(git_dir):
        arch = subprocess.run(["git", "--git-dir", git_dir, "archive", COMMIT, "cardillo", EXAMPLE],
                              capture_output=True)
        if arch.returncode == 0:
            subprocess.run(["tar", "-x", "-C", tmp], input=arch.stdout, check=True)
            return tmp
        sys.stderr.write("git archive %s failed: %s\n" % (COMMIT, arch.stderr.decode().strip()))
        return None
    return src if os.path.isfile(os.path.join(src, EXAMPLE)) else None


def workbook():
    here = os.path.dirname(os.path.abspath(__file__))
    root = os.path.dirname(os.path.dirname(here))
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(root, "target"))
    exe = os.path.join(target, "release", "examples", "peer_runs")
    if not os.path.exists(exe):
        subprocess.run(["cargo", "build", "--release", "--example", "peer_runs"], cwd=root, check=True)
    return json.loads(subprocess.run([exe, "painleve"], capture_output=True, text=True, check=True).stdout)


def as_cardillo(w):
    """The workbook's state in cardillo's coordinates: phi = theta + 90 deg (from the floor,
    top to the left), phi' = theta'. Right after the impulse: the first sample is in flight
    (no spring, no damper: omega constant, G ballistic), so gravity is undone over the gap."""
    s = w["first_sample_after"]["state"]
    gap = w["first_sample_after"]["t_s"] - w["painleve_time_s"]
    after = [s["vx_g_mps"], s["vz_g_mps"] + G * gap, s["omega_radps"]]
    e = w["end"]["state"]
    # cardillo's x is the centre's from x = 0; the workbook's C starts at x = 0, so its
    # centre starts at s cos(31 deg) to the left
    return after, [e["x_g_m"] + math.cos(math.radians(31.0)), e["z_g_m"], e["theta_rad"] + 1.5707963267948966], [e["vx_g_mps"], e["vz_g_mps"], e["omega_radps"]]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--cardillo", default=os.environ.get("CARDILLO_DIR"), help="cardillo checkout or git dir")
    p.add_argument("--python", default=sys.executable, help="interpreter with cardillo's dependencies")
    p.add_argument("--runs", default="moreau:5e-3,moreau:1e-3,moreau:2e-4,moreau:5e-5,"
                   "backward-euler:5e-3,backward-euler:1e-3",
                   help="solver:dt list (solvers: moreau, backward-euler)")
    a = p.parse_args()
    if not a.cardillo or not os.path.exists(a.cardillo):
        sys.stderr.write("cardillo not found: set CARDILLO_DIR or --cardillo (a checkout of "
                         "github.com/cardilloproject/cardillo); skipped\n")
        return
    probe = subprocess.run([a.python, "-c", "import numpy, scipy, matplotlib, tqdm, dill, cachetools, trimesh, meshio\n"
                            "assert numpy.__version__ < '2' and scipy.__version__ < '1.13', "
                            "'numpy %s, scipy %s: cardillo of 2024 needs numpy < 2, scipy 1.12' "
                            "% (numpy.__version__, scipy.__version__)"], capture_output=True, text=True)
    if probe.returncode != 0:
        sys.stderr.write("cardillo's dependencies are missing under %s (%s); skipped (see the venv in "
                         "benches/peers/README.md)\n" % (a.python, probe.stderr.strip().splitlines()[-1]))
        return
    w = workbook()
    after, q_end, u_end = as_cardillo(w)
    print("workbook: inconsistent slide at t = %.6f s, theta = %.6f rad (phi = %.4f deg), mu_P = %.6f; "
          "impulse (P_x, P_z) = (%.4f, %.4f) N s" % (w["painleve_time_s"], w["theta_rad"],
          (w["theta_rad"] + 1.5707963267948966) * 57.29577951308232, w["mu_p"], *w["impulse_ns"]))
    print("workbook: after it (vx_G, vz_G, phi') = (%.4f, %.4f, %.4f); at t = %.3f s q = (%.4f, %.4f, %.4f), "
          "u = (%.4f, %.4f, %.4f); outcome %s" % (*after, w["end"]["t_s"], *q_end, *u_end, w["outcome"]))
    times = [x["t_s"] for x in w["samples"]]
    print("workbook samples (t, phi, vx_G, vz_G, phi'): " + "; ".join(
        "%.3f %.4f %.4f %.4f %.4f" % (x["t_s"], x["state"]["theta_rad"] + 1.5707963267948966, x["state"]["vx_g_mps"],
                                      x["state"]["vz_g_mps"], x["state"]["omega_radps"]) for x in w["samples"]))
    # chapter 8, section 1, slide right (sigma = -1) on a still floor, no spring: F_z = M N / D,
    # D = I_G + M l_G^2 sin(theta) (sin(theta) + mu cos(theta)), N = I_G (g - l_G theta'^2 cos(theta))
    for x in w["samples"][-2:]:
        th, om = x["state"]["theta_rad"], x["state"]["omega_radps"]
        d = 1 / 3 + math.sin(th) * (math.sin(th) + 5 / 3 * math.cos(th))
        n = (G - om * om * math.cos(th)) / 3
        print("workbook at t = %.4f s: D = %.2e kg m^2, N = %.3f, F_z = M N / D = %.0f N" % (x["t_s"], d, n, n / d))
    with tempfile.TemporaryDirectory() as tmp:
        root = cardillo_tree(a.cardillo, tmp)
        if root is None:
            sys.stderr.write("no %s at %s in %s; skipped\n" % (EXAMPLE, COMMIT, a.cardillo))
            return
        for run in a.runs.split(","):
            solver, dt = run.split(":")
            r = subprocess.run([a.python, "-c", CHILD, root, solver, dt, str(T_COMPARE), json.dumps(times)],
                               capture_output=True, text=True)
            if r.returncode != 0:
                print("cardillo %s dt = %s: failed (%s)" % (solver, dt, r.stderr.strip().splitlines()[-1]))
                continue
            c = json.loads(r.stdout.strip().splitlines()[-1])
            print("cardillo %-14s dt = %-6s: impact at t = %.4f s (P_N = %.4f, P_F = %.4f N s; step before "
                  "P_N = %.4f); after (vx, vy, phi') = (%.4f, %.4f, %.4f); at t = %.3f q = (%.4f, %.4f, %.4f) "
                  "u = (%.4f, %.4f, %.4f); %.1f s" % (solver, dt, c["impact_step_t_s"], c["P_N"], c["P_F"],
                  c["P_N_before"], *c["u_after"], c["t_cmp_s"], *c["q_cmp"], *c["u_cmp"], c["wall_s"]))
            print("    last step in contact before it: t = %.4f s; samples (t, phi, vx, vy, phi'): %s" % (
                c["last_contact_t_s"], "; ".join("%.3f %.4f %.4f %.4f %.4f" % (t, q[2], *u) for t, q, u in c["samples"])))


if __name__ == "__main__":
    main()
