#!/usr/bin/env python3
"""SciPy peer of the workbook's block benchmark (section 3.1.2 scene).

A block on a plate z_p = delta sin(omega t), bias force F = b m g, Coulomb friction mu,
plastic landings with impulsive Coulomb friction. Modes flight / stick / slide+ / slide-,
each integrated by scipy.integrate.solve_ivp (RK45 = Dormand-Prince 5(4), the workbook's
method) with terminal events located by SciPy; the state is relative to the plate,
y = [u, w, h, vh] = [x, x', z - z_p, z' - z_p'] (the plate does not move in x).

Prints one JSON object: mean drift over the window, wall time (minimum of repeats),
rhs evaluations and events. Run: python3 benches/peers/block_scipy.py --help
"""
import argparse
import json
import math
import time

from scipy.integrate import solve_ivp


def simulate(f_hz, gamma, mu, bias, g, transient, cycles, rtol, atol):
    w = 2.0 * math.pi * f_hz
    delta = gamma * g / (w * w)
    period = 2.0 * math.pi / w
    b = bias * g
    az = lambda t: -delta * w * w * math.sin(w * t)  # plate acceleration
    normal = lambda t: g + az(t)  # N/m in contact

    def rhs(mode):
        if mode == "flight":
            return lambda t, y: [y[1], b, y[3], -g - az(t)]
        if mode == "stick":
            return lambda t, y: [0.0, 0.0, 0.0, 0.0]
        s = 1.0 if mode == "slide+" else -1.0
        return lambda t, y: [y[1], b - s * mu * normal(t), 0.0, 0.0]

    def events(mode):
        def ev(fn):
            fn.terminal = True
            fn.direction = -1
            return fn
        if mode == "flight":
            return [ev(lambda t, y: y[2])]
        evs = [ev(lambda t, y: normal(t))]
        if mode == "stick":
            evs.append(ev(lambda t, y: mu * normal(t) - abs(b)))
        else:
            s = 1.0 if mode == "slide+" else -1.0
            evs.append(ev(lambda t, y: s * y[1]))
        return evs

    def contact_mode(t, vx):
        if vx > 0:
            return "slide+"
        if vx < 0:
            return "slide-"
        if mu * normal(t) >= abs(b):
            return "stick"
        return "slide+" if b > 0 else "slide-"

    t_a, t_b = transient * period, (transient + cycles) * period
    t, y, mode = 0.0, [0.0, 0.0, 0.0, 0.0], "stick"
    x_a, nfev, nev = None, 0, 0
    while t < t_b:
        sol = solve_ivp(rhs(mode), (t, t_b), y, method="RK45", rtol=rtol, atol=atol,
                        events=events(mode), max_step=period / 20.0, dense_output=True)
        nfev += sol.nfev
        hit = [(te[0], i) for i, te in enumerate(sol.t_events) if len(te)]
        t1 = min(hit)[0] if hit else sol.t[-1]
        if x_a is None and t1 >= t_a:
            x_a = sol.sol(t_a)[0]
        if not hit:
            t, y = t1, list(sol.y[:, -1])
            break
        te, i = min(hit)
        ye = sol.y_events[i][0]
        nev += 1
        u, vx, h, vh = ye
        if mode == "flight":  # plastic landing, impulsive Coulomb friction
            slip = mu * max(-vh, 0.0)
            vx = 0.0 if abs(vx) <= slip else vx - math.copysign(slip, vx)
            mode = "flight" if normal(te) <= 0 else contact_mode(te, vx)
            y = [u, vx, 0.0, 0.0]
        elif i == 0:  # takeoff
            mode, y = "flight", [u, vx, 0.0, 0.0]
        elif mode == "stick":
            mode, y = ("slide+" if b >= 0 else "slide-"), [u, 0.0, 0.0, 0.0]
        else:
            mode, y = contact_mode(te, 0.0), [u, 0.0, 0.0, 0.0]
        t = te
    return (y[0] - x_a) / (t_b - t_a), nfev, nev


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--frequency-hz", type=float, default=30.0)
    p.add_argument("--gamma", type=float, default=2.5)
    p.add_argument("--mu", type=float, default=0.4)
    p.add_argument("--bias", type=float, default=0.02)
    p.add_argument("--g-mps2", type=float, default=9.81)
    p.add_argument("--transient", type=int, default=10)
    p.add_argument("--cycles", type=int, default=40)
    p.add_argument("--tol", type=float, default=1e-8, help="rtol = atol")
    p.add_argument("--repeats", type=int, default=3)
    a = p.parse_args()
    best = math.inf
    for _ in range(max(1, a.repeats)):
        t0 = time.perf_counter()
        v, nfev, nev = simulate(a.frequency_hz, a.gamma, a.mu, a.bias, a.g_mps2, a.transient, a.cycles, a.tol, a.tol)
        best = min(best, time.perf_counter() - t0)
    print(json.dumps({"mean_velocity_mps": v, "wall_s": best, "rhs_evals": nfev, "events": nev}))


if __name__ == "__main__":
    main()
