#!/usr/bin/env python3
"""MuJoCo peer of chapter 8's uniform stick (a toothpick) on the vibrating plate.

The scene of `workbook stick-with-inertia --tip-mass-kg 0 --rod-mass-kg M`: a rigid rod of
length L and mass M spread uniformly (no tip mass), the torsion spring k and damper gamma
of chapter 6 pulling its angle from the vertical towards theta_0 (chapter 8, section 1:
a couple between the rod and the laboratory), Coulomb friction mu at its foot C, the plate
z_s = delta cos(omega t), from rest at the static angle k (theta - theta_0) = M g (L/2)
sin theta with C on the plate at x = 0.

In MuJoCo (PyPI `mujoco`): the rod is a body with three joints to the world, slide x,
slide z and a hinge about y at C, so the hinge angle is the angle from the vertical and
the hinge's own spring (stiffness k, springref theta_0) and damping gamma are exactly the
chapter's couple; its inertia is given (mass M at L/2, M L^2/12 about the centre); it
touches the plate with a small sphere at C (radius --foot-radius-m, friction mu, condim 3).
The plate is a heavy box (1e4 kg, gravity compensated) on a slide joint whose position
and velocity are set to delta cos(omega t) and -delta omega sin(omega t) before every
step, with a force giving it the acceleration -delta omega^2 cos(omega t) in the step's
contact solve (a mocap body would carry no velocity into the contact). Contacts are MuJoCo's soft ones: solref =
(--solref-steps x the time step, --damping-ratio, default 1), default solimp; friction cone
pyramidal (default) or elliptic (--cone).

For each time step of --steps it prints the mean horizontal speed of C, x_C(T)/T, beside
the workbook's on the same scene (`workbook stick-with-inertia ... --json`), and how far
the foot sank into the plate at most. Needs `pip install mujoco` (without it: a message
on stderr, exit 0). Run: python3 benches/peers/mujoco_stick.py --help
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

try:
    import mujoco
except ImportError as e:
    sys.stderr.write("mujoco_stick.py: %s (pip install mujoco); skipped\n" % e)
    sys.exit(0)

PLATE_KG = 1e4  # heavy: the rod's reaction moves it by 1e-4 of the rod's own response
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def static_angle(k, th0, w_lever):
    """Solves k (theta - theta_0) = w_lever sin theta by bisection on [theta_0, pi/2)."""
    lo, hi = th0, math.pi / 2
    f = lambda t: k * (t - th0) - w_lever * math.sin(t)
    if f(hi) < 0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
    return 0.5 * (lo + hi)


def model_xml(p, h, a):
    L, M, r = p["length_m"], p["rod_mass_kg"], a.foot_radius_m
    i_g = M * L * L / 12
    return f"""
<mujoco>
  <compiler angle="radian"/>
  <option timestep="{h}" gravity="0 0 {-p['g_mps2']}" cone="{a.cone}"/>
  <worldbody>
    <body name="plate" gravcomp="1">
      <joint name="plate_z" type="slide" axis="0 0 1"/>
      <inertial pos="0 0 0" mass="{PLATE_KG}" diaginertia="1 1 1"/>
      <geom type="box" pos="0 0 -0.01" size="100 0.5 0.01" friction="{p['mu']} 0 0"
            solref="{a.solref_steps * h} {a.damping_ratio}" solimp="{a.solimp}"/>
    </body>
    <body name="rod">
      <joint name="x" type="slide" axis="1 0 0"/>
      <joint name="z" type="slide" axis="0 0 1"/>
      <joint name="theta" type="hinge" axis="0 1 0" stiffness="{p['stiffness_nm_per_rad']}"
             springref="{p['theta0_rad']}" damping="{p['damping_nms_per_rad']}"/>
      <inertial pos="0 0 {L / 2}" mass="{M}" diaginertia="{i_g} {i_g} {i_g * 1e-3}"/>
      <geom type="sphere" size="{r}" pos="0 0 {r}" friction="{p['mu']} 0 0" solref="{a.solref_steps * h} {a.damping_ratio}"
            solimp="{a.solimp}"/>
      <geom type="capsule" fromto="0 0 {2 * r} 0 0 {L}" size="{r / 2}" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>"""


def run(p, h, a):
    m = mujoco.MjModel.from_xml_string(model_xml(p, h, a))
    d = mujoco.MjData(m)
    w = 2 * math.pi * p["frequency_hz"]
    delta = p["gamma"] * p["g_mps2"] / w ** 2
    th = static_angle(p["stiffness_nm_per_rad"], p["theta0_rad"], p["rod_mass_kg"] * p["g_mps2"] * p["length_m"] / 2)
    # C (the hinge, the body origin) at x = 0 on the plate's top at t = 0: the sphere's
    # centre sits r above C along the rod, so C is lowered to touch
    r = a.foot_radius_m
    d.qpos[:] = [delta, 0.0, delta - r * math.cos(th) + r, th]
    steps = int(round(a.duration_s / h))
    sink = 0.0
    c = time.perf_counter()
    for n in range(steps):
        t = n * h
        d.qpos[0], d.qvel[0] = delta * math.cos(w * t), -delta * w * math.sin(w * t)
        d.qfrc_applied[0] = PLATE_KG * -delta * w * w * math.cos(w * t)  # its acceleration in the step's solve
        mujoco.mj_step(m, d)
        if abs(d.qpos[3]) > math.pi / 2:
            return {"fell_at_s": (n + 1) * h}
        if d.ncon:
            sink = max(sink, -d.contact[0].dist)
    return {"mean_velocity_mps": d.qpos[1] / a.duration_s, "static_angle_rad": th,
            "max_penetration_m": sink, "wall_s": time.perf_counter() - c}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scene", default="jamming", help="workbook scene (jamming is the default)")
    p.add_argument("--rod-mass-kg", type=float, default=1.0)
    p.add_argument("--duration-s", type=float, default=10.0)
    p.add_argument("--steps", default="1e-4,3e-5,1e-5", help="MuJoCo time steps (s)")
    p.add_argument("--cone", default="pyramidal", choices=["pyramidal", "elliptic"])
    p.add_argument("--solref-steps", type=float, default=2.0, help="contact time constant in time steps (>= 2)")
    p.add_argument("--damping-ratio", type=float, default=1.0, help="solref's damping ratio (1: critical)")
    p.add_argument("--solimp", default="0.9 0.95 0.001", help="contact impedance (MuJoCo's default)")
    p.add_argument("--foot-radius-m", type=float, default=1e-4)
    a = p.parse_args()
    exe = os.path.join(os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target")), "release", "workbook")
    if not os.path.exists(exe):
        subprocess.run(["cargo", "build", "--release", "--bin", "workbook"], cwd=ROOT, check=True)
    wb = json.loads(subprocess.run([exe, "stick-with-inertia", "--scene", a.scene, "--quick", "--tip-mass-kg", "0",
                                    "--rod-mass-kg", str(a.rod_mass_kg), "--duration-s", str(a.duration_s),
                                    "--no-figures", "--json"], capture_output=True, text=True, check=True).stdout)
    par = dict(wb["params"])
    par["rod_mass_kg"] = a.rod_mass_kg
    v_wb = wb["results"]["mean_velocity_mps"]
    print("scene %s, uniform rod %g kg, %g s; workbook (event-driven, rigid contact): %.5f m/s (%s, %d impacts)"
          % (a.scene, a.rod_mass_kg, a.duration_s, v_wb, wb["results"]["outcome"], wb["results"]["impacts"]))
    print("MuJoCo %s, cone %s, solref (%g h, %g), solimp (%s), foot sphere r = %g m:"
          % (mujoco.__version__, a.cone, a.solref_steps, a.damping_ratio, a.solimp, a.foot_radius_m))
    for h in [float(x) for x in a.steps.split(",")]:
        r = run(par, h, a)
        if "fell_at_s" in r:
            print("  h = %-6g: fell at t = %.4f s" % (h, r["fell_at_s"]))
            continue
        print("  h = %-6g: mean speed %.5f m/s (relative to the workbook %+.3f), deepest penetration %.2e m, %.1f s"
              % (h, r["mean_velocity_mps"], r["mean_velocity_mps"] / v_wb - 1, r["max_penetration_m"], r["wall_s"]))


if __name__ == "__main__":
    main()
