#!/usr/bin/env python3
"""heyoka.py peer of the workbook's massless stick (chapter 6, document sections 4 and 5).

The model is `stick_scipy.py`'s (a line-by-line port of src/physics/stick: the same
transition rules, impact maps and mode selection, imported from it); what changes is the
integration. Every mode, flight included, is integrated by heyoka's Taylor method (LLVM
JIT, tolerance --tol, default 1e-8) and every switch is found by heyoka's own terminal
events on the Taylor polynomials:

- flight, state (x_P, z_P, vx_P, vz_P, theta): P ballistic, gamma theta' = -k (theta -
  theta_0) (C.3); event: C's height over the plate, z_P - L cos theta - delta cos omega t,
  falling through zero (the landing);
- pivot, state (theta, theta') (C.6); events: F_z (C.7) falling through zero, mu F_z -+ F_x
  falling through zero (the cone), cos theta (fallen);
- slide left / right, state (x_C, theta, x_C', theta') (C.9 to C.14); events: the jam
  denominator L (sin theta - sigma mu cos theta), the normal force's numerator (the couple
  times the denominator's sign, a parameter of the integrator), the slip velocity
  reaching zero, cos theta, sin theta, the slip turning (an error).

For the default (self-locking) scene and the authors' scene, both 1 s from rest at the
static angle, it runs the workbook (`stick-state-machine --events FILE`) and itself,
matches the switches one by one (same index, same modes, |dt| < --match-s) and times both
at their own accuracy: heyoka at tol 1e-8 (a run's wall time, minimum of --repeats after
compilation, and the part spent inside heyoka's propagate_until), the workbook at DOP853
rtol 1e-10 in-process (`target/release/examples/peer_runs stick SCENE 1 REPEATS`, minimum
of the repeats). Prints drive cycles/s of each and the ratio.

Needs heyoka (`pip install heyoka`; without it: a message on stderr, exit 0) and scipy
(the base port). Run: python3 benches/peers/heyoka_stick.py --help
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from types import SimpleNamespace

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
try:
    import heyoka as hy
    import stick_scipy as base
except ImportError as e:
    sys.stderr.write("heyoka_stick.py: %s (pip install heyoka scipy); skipped\n" % e)
    sys.exit(0)

NAMES = {base.FLIGHT: "flight", base.PIVOT: "pivot", base.LEFT: "slide_left", base.RIGHT: "slide_right"}
NEG, POS, ANY = hy.event_direction.negative, hy.event_direction.positive, hy.event_direction.any


def integrators(s, tol):
    """One Taylor integrator per mode, compiled once (state, events as in the docstring)."""
    m, L, g, k, gam, mu, th0 = s.m, s.L, s.g, s.k, s.gam, s.mu, s.th0
    a_s = -s.d * s.w ** 2 * hy.cos(s.w * hy.time)  # plate acceleration, z_s = delta cos(omega t)
    # a short fixed cooldown: heyoka's automatic one is long when the event function's
    # rate is near zero at the trigger (a slide entered at the cone's edge), and it would
    # hide that slide's end
    te = lambda e, d: hy.t_event(e, direction=d, cooldown=1e-9)
    ta = {}
    xp, zp, vxp, vzp, th = hy.make_vars("xp", "zp", "vxp", "vzp", "th")
    ta[base.FLIGHT] = hy.taylor_adaptive(
        [(xp, vxp), (zp, vzp), (vxp, 0.0 * vxp), (vzp, -g + 0.0 * vzp), (th, -(k / gam) * (th - th0))],
        [0.0] * 5, tol=tol, t_events=[te(zp - L * hy.cos(th) - s.d * hy.cos(s.w * hy.time), NEG)])
    th, om = hy.make_vars("th", "om")
    sn, cs = hy.sin(th), hy.cos(th)
    thdd = ((g + a_s) * m * L * sn - (k * (th - th0) + gam * om)) / (m * L * L)  # C.6
    fx = m * L * (thdd * cs - om * om * sn)
    fz = m * (a_s - L * (thdd * sn + om * om * cs) + g)  # C.7
    ta[base.PIVOT] = hy.taylor_adaptive(
        [(th, om), (om, thdd)], [0.0, 0.0], tol=tol,
        t_events=[te(fz, NEG), te(mu * fz - fx, NEG), te(mu * fz + fx, NEG), te(cs, NEG)])
    x, th, vx, om = hy.make_vars("x", "th", "vx", "om")
    sn, cs = hy.sin(th), hy.cos(th)
    for mode, sg in base.SIGMA.items():
        den = L * (sn - sg * mu * cs)
        torque = k * (th - th0) + gam * om
        fz = torque / den  # C.9 / C.11
        thdd = (a_s + g - fz / m - L * cs * om * om) / (L * sn)  # C.14
        xdd = sg * mu * fz / m - L * (thdd * cs - om * om * sn)
        ta[mode] = hy.taylor_adaptive(
            [(x, vx), (th, om), (vx, xdd), (om, thdd)], [0.0] * 4, tol=tol, pars=[1.0],
            t_events=[te(den, ANY), te(torque * hy.par[0], NEG), te(-sg * vx, NEG), te(cs, NEG),
                      te(sn, ANY), te(sg * vx - 1e-9, POS)])
    return ta


class HeyokaStick(base.Stick):
    def __init__(self, a, ta):
        super().__init__(a)
        self.ta, self.switches, self.in_heyoka = ta, [], 0.0

    def propagate(self, ta, t0, state, t_end):
        ta.time = t0
        ta.state[:] = state
        ta.reset_cooldowns()
        c = time.perf_counter()
        oc = int(ta.propagate_until(t_end)[0])
        # An event found at the very start is the condition that just ended the previous
        # mode, seen again at the root (the slip of a slide entered at the cone's edge
        # grows as t^2, so round-off can give it either sign): heyoka has now put that
        # event on cooldown, so going on skips it. (The workbook enters a mode at the
        # first point past the root instead.)
        if -(1 << 32) < oc < 0 and ta.time == t0:
            oc = int(ta.propagate_until(t_end)[0])
        self.in_heyoka += time.perf_counter() - c
        if oc < -(1 << 32):  # success, time limit, ...: no terminal event
            if oc != int(hy.taylor_outcome.time_limit):
                raise base.Invalid("heyoka: %s" % hy.taylor_outcome(oc))
            return None
        return -oc - 1  # terminal event i ends the step with outcome -(i + 1)

    def fly(self, t0, y0, t_end):
        xp, zp, vxp, vzp = self.tip(y0)
        ta = self.ta[base.FLIGHT]
        i = self.propagate(ta, t0, [xp, zp, vxp, vzp, y0[2]], t_end)
        xp, zp, vxp, vzp, th = ta.state
        om = -self.rate * (th - self.th0)
        s, c = math.sin(th), math.cos(th)
        return ta.time, [xp - self.L * s, zp - self.L * c, th, vxp - self.L * om * c, vzp + self.L * om * s, om], i == 0

    def contact(self, mode, t0, y0, t_end, tol):
        ta = self.ta[mode]
        if mode == base.PIVOT:
            i = self.propagate(ta, t0, [y0[2], y0[5]], t_end)
            th, om = ta.state
            return ta.time, self.full(ta.time, [y0[0], th, 0.0, om]), i
        ta.pars[0] = math.copysign(1.0, self.den(base.SIGMA[mode], y0[2]))
        i = self.propagate(ta, t0, [y0[0], y0[2], y0[3], y0[5]], t_end)
        return ta.time, self.full(ta.time, list(ta.state)), i

    def run(self, theta_start, cycles, tol):
        zs, vs, _ = self.plate(0.0)
        t, t_end = 0.0, cycles * self.T
        mode, y = self.select_contact(t, [0.0, zs, theta_start, 0.0, vs, 0.0])
        while t < t_end:
            before = mode
            if mode == base.FLIGHT:
                t, y, landed = self.fly(t, y, t_end)
                if landed:
                    mode, y = self.landing(t, y)
                    self.switches.append((t, before, mode))
            else:
                t, y, i = self.contact(mode, t, y, t_end, tol)
                if i is not None:
                    mode, y = self.transition(mode, i, t, y)
                    self.switches.append((t, before, mode))
        return y[0] / t_end


def workbook_run(scene, duration):
    exe = os.path.join(os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target")), "release")
    for path, args in [(os.path.join(exe, "workbook"), ["--release", "--bin", "workbook"]),
                       (os.path.join(exe, "examples", "peer_runs"), ["--release", "--example", "peer_runs"])]:
        if not os.path.exists(path):
            subprocess.run(["cargo", "build"] + args, cwd=ROOT, check=True)
    with tempfile.TemporaryDirectory() as tmp:
        ev = os.path.join(tmp, "events.csv")
        out = subprocess.run([os.path.join(exe, "workbook"), "stick-state-machine", "--scene", scene, "--quick",
                              "--duration-s", str(duration), "--events", ev, "--no-figures", "--json"],
                             capture_output=True, text=True, check=True)
        with open(ev) as f:
            switches = [(float(r["t_s"]), r["from"], r["to"]) for r in csv.DictReader(f)]
    return json.loads(out.stdout), switches, os.path.join(exe, "examples", "peer_runs")


def compare(scene, a):
    wb, wsw, peer_runs = workbook_run(scene, a.duration_s)
    p = wb["params"]
    ns = SimpleNamespace(length_m=p["length_m"], mass_kg=p["mass_kg"], k=p["stiffness_nm_per_rad"],
                         gamma_damper=p["damping_nms_per_rad"], mu=p["mu"], theta0_rad=p["theta0_rad"],
                         g_mps2=p["g_mps2"], gamma=p["gamma"], frequency_hz=p["frequency_hz"], method=None)
    c = time.perf_counter()
    ta = integrators(base.Stick(ns), a.tol)
    compile_s = time.perf_counter() - c
    cycles = a.duration_s * p["frequency_hz"]
    best, in_hy = math.inf, math.inf
    for _ in range(a.repeats):
        s = HeyokaStick(ns, ta)
        c = time.perf_counter()
        v = s.run(wb["results"]["start_angle_rad"], cycles, a.tol)
        wall = time.perf_counter() - c
        best, in_hy = min(best, wall), min(in_hy, s.in_heyoka)
    hsw = [(t, NAMES[f], NAMES[g]) for t, f, g in s.switches]
    n = min(len(hsw), len(wsw))
    dts = [abs(hsw[i][0] - wsw[i][0]) for i in range(n) if hsw[i][1:] == wsw[i][1:]]
    match = sum(1 for i in range(n) if hsw[i][1:] == wsw[i][1:] and abs(hsw[i][0] - wsw[i][0]) < a.match_s)
    timing = json.loads(subprocess.run([peer_runs, "stick", scene, str(a.duration_s), str(a.repeats)],
                                       capture_output=True, text=True, check=True).stdout)
    print("%s scene, %g s (%.0f drive cycles) from rest at %.6f rad:" % (scene, a.duration_s, cycles,
          wb["results"]["start_angle_rad"]))
    print("  switches: heyoka %d, workbook %d; matching in modes and within %g s: %d/%d; largest |dt| among "
          "same-mode pairs %.2e s" % (len(hsw), len(wsw), a.match_s, match, len(wsw), max(dts, default=math.nan)))
    print("  mean speed of C: heyoka %.10f m/s, workbook %.10f m/s (relative difference %.1e)"
          % (v, timing["mean_velocity_mps"], v / timing["mean_velocity_mps"] - 1))
    print("  heyoka tol %g: %.3e s per run (%.0f cycles/s; inside propagate_until %.3e s, %.0f cycles/s); "
          "compilation %.1f s" % (a.tol, best, cycles / best, in_hy, cycles / in_hy, compile_s))
    print("  workbook DOP853 rtol 1e-10: %.3e s per run (%.0f cycles/s)" % (timing["wall_s"], timing["cycles_per_s"]))
    print("  ratio heyoka / workbook wall time: %.2f (heyoka's integration alone: %.2f)"
          % (best / timing["wall_s"], in_hy / timing["wall_s"]))
    for i in range(n):
        if hsw[i][1:] != wsw[i][1:] or abs(hsw[i][0] - wsw[i][0]) >= a.match_s:
            print("  first mismatch #%d: heyoka %s, workbook %s" % (i + 1, hsw[i], wsw[i]))
            break


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--scenes", default="jamming,authors", help="workbook scenes (jamming is the default)")
    p.add_argument("--duration-s", type=float, default=1.0)
    p.add_argument("--tol", type=float, default=1e-8, help="heyoka's tolerance")
    p.add_argument("--repeats", type=int, default=20)
    p.add_argument("--match-s", type=float, default=1e-6, help="largest time difference of a matching switch")
    a = p.parse_args()
    print("load average at start: %.2f %.2f %.2f" % os.getloadavg())
    for scene in a.scenes.split(","):
        compare(scene, a)
    print("load average at end: %.2f %.2f %.2f" % os.getloadavg())


if __name__ == "__main__":
    main()
