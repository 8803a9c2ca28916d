#!/usr/bin/env python3
"""SciPy peer of the workbook's stick simulation (document sections 4 and 5).

The same model as src/physics/stick (massless rod CP, point mass m at P, torsion spring
k and damper gamma towards theta_0, plate z_s = delta cos(omega t), Coulomb friction mu
at C): flight in closed form (ballistic P, theta relaxing as exp(-k t / gamma)), landing
located by brentq on the same sampling grid; pivot (C.6) and the two slides (C.9-C.14)
integrated by scipy.integrate.solve_ivp (RK45 = Dormand-Prince 5(4)) with terminal
events; the same transition rules (Table 1 reactions, the sticking impact C.15 with the
actual angle, the impulse-free landing, the jam on the self-locking edge).

Prints one JSON object: mean horizontal speed of C, wall time (minimum of repeats),
rhs evaluations, landings. Run: python3 benches/peers/stick_scipy.py --help
"""
import argparse
import json
import math
import time

from scipy.integrate import solve_ivp
from scipy.optimize import brentq

FLIGHT, PIVOT, LEFT, RIGHT = "F", "P", "L", "R"
SIGMA = {LEFT: 1.0, RIGHT: -1.0}


class Invalid(Exception):
    pass


class Stick:
    def __init__(self, a):
        self.L, self.m, self.k, self.gam, self.mu = a.length_m, a.mass_kg, a.k, a.gamma_damper, a.mu
        self.th0, self.g = a.theta0_rad, a.g_mps2
        self.method = a.method
        self.w = 2 * math.pi * a.frequency_hz
        self.d = a.gamma * self.g / self.w ** 2
        self.T = 2 * math.pi / self.w
        self.rate = self.k / self.gam
        self.nfev = 0
        self.hops = 0

    # state y = [xc, zc, th, vxc, vzc, om]
    def plate(self, t):
        ph = self.w * t + math.pi / 2
        s, c = math.sin(ph), math.cos(ph)
        return self.d * s, self.d * self.w * c, -self.d * self.w ** 2 * s

    def tip(self, y):
        s, c = math.sin(y[2]), math.cos(y[2])
        return (y[0] + self.L * s, y[1] + self.L * c, y[3] + self.L * c * y[5], y[4] - self.L * s * y[5])

    def torque(self, th, om):
        return self.k * (th - self.th0) + self.gam * om

    def pivot_eval(self, t, th, om):
        m, L, g = self.m, self.L, self.g
        a_s = self.plate(t)[2]
        s, c = math.sin(th), math.cos(th)
        thdd = ((g + a_s) * m * L * s - self.torque(th, om)) / (m * L * L)  # C.6
        ax = L * (thdd * c - om * om * s)
        az = a_s - L * (thdd * s + om * om * c)  # C.7
        return thdd, 0.0, m * ax, m * (az + g)

    def den(self, sigma, th):
        return self.L * (math.sin(th) - sigma * self.mu * math.cos(th))

    def slide_eval(self, sigma, t, th, om):
        m, L, g, mu = self.m, self.L, self.g, self.mu
        a_s = self.plate(t)[2]
        s, c = math.sin(th), math.cos(th)
        fz = self.torque(th, om) / (L * (s - sigma * mu * c))  # C.9 / C.11
        thdd = (a_s + g - fz / m - L * c * om * om) / (L * s)  # C.14
        xdd = sigma * mu * fz / m - L * (thdd * c - om * om * s)
        return thdd, xdd, sigma * mu * fz, fz

    def full(self, t, u):  # contact state [xc, th, vxc, om] -> y
        zs, vs, _ = self.plate(t)
        return [u[0], zs, u[1], u[2], vs, u[3]]

    # ---- transitions (src/physics/stick/rules.rs, collision.rs)
    def takeoff(self, t, y):
        L = self.L
        _, _, vxp, vzp = self.tip(y)
        zs, vs, a_s = self.plate(t)
        s, c = math.sin(y[2]), math.cos(y[2])
        om = -self.rate * (y[2] - self.th0)
        a = [y[0], zs, y[2], vxp - L * om * c, vzp + L * om * s, om]
        h_d = a[4] - vs
        h_dd = -self.g + L * (c * om * om - s * self.rate * om) - a_s
        tol_v = 1e-6 * max(self.d * self.w, math.sqrt(self.g * L))
        if h_d < -tol_v or (h_d <= tol_v and h_dd < 0):
            return None
        return FLIGHT, a

    def try_slide(self, mode, t, y):
        if abs(math.sin(y[2])) < 1e-9:
            return None
        _, xdd, _, fz = self.slide_eval(SIGMA[mode], t, y[2], y[5])
        # SciPy returns the event root itself, the workbook the first point past it (where
        # the slide's acceleration has just turned): allow round-off at the switch.
        if fz < 0 or SIGMA[mode] * xdd > 1e-9 or not math.isfinite(fz):
            return None
        return mode, y

    def select_contact(self, t, y, allow_pivot=True):
        y = list(y)
        y[3] = 0.0
        _, _, fx, fz = self.pivot_eval(t, y[2], y[5])
        if allow_pivot and fz >= 0 and abs(fx) <= self.mu * fz:
            return PIVOT, y
        drive, other = (LEFT, RIGHT) if fx > 0 else (RIGHT, LEFT)
        order = [drive, FLIGHT, other] if fz >= 0 else [FLIGHT, drive, other]
        for mode in order:
            nxt = self.takeoff(t, y) if mode == FLIGHT else self.try_slide(mode, t, y)
            if nxt is not None:
                return nxt
        raise Invalid("no consistent contact mode at t = %.6f" % t)

    def sticking_impact(self, t, y, lever):
        L, m = self.L, self.m
        _, _, vxp, vzp = self.tip(y)
        zs, vs, _ = self.plate(t)
        s, c = math.sin(lever), math.cos(lever)
        ux, uz = vxp, vzp - vs
        w = ux * s + uz * c
        om = (ux * c - uz * s) / L  # C.15
        return [y[0], zs, lever, 0.0, vs, om], -m * w

    def landing(self, t, y):
        self.hops += 1
        _, _, vxp, vzp = self.tip(y)
        vs = self.plate(t)[1]
        s, c = math.sin(y[2]), math.cos(y[2])
        w = vxp * s + (vzp - vs) * c
        if abs(math.tan(y[2])) <= self.mu and w < 0:
            after, _ = self.sticking_impact(t, y, y[2])
            return self.select_contact(t, after)
        if abs(s) < 1e-9:
            raise Invalid("vertical landing outside the cone")
        zs = self.plate(t)[0]
        om = (vs - vzp) / (self.L * s)
        a = [y[0], zs, y[2], vxp - self.L * om * c, vs, om]
        if a[3] != 0:
            mode = LEFT if a[3] < 0 else RIGHT
            if self.slide_eval(SIGMA[mode], t, a[2], a[5])[3] < 0:
                nxt = self.takeoff(t, a)
                if nxt is None:
                    raise Invalid("inconsistent lift-off")
                return nxt
            return mode, a
        return self.select_contact(t, a)

    def jam(self, t, y):
        after, lam = self.sticking_impact(t, y, y[2])
        if lam < 0:
            raise Invalid("tensile jam")
        return self.select_contact(t, after)

    # ---- flight: closed form, landing by brentq on the model's sampling grid
    def flight_state(self, t0, y0, t):
        tau = t - t0
        xp0, zp0, vxp0, vzp0 = self.tip(y0)
        xp, zp, vzp = xp0 + vxp0 * tau, zp0 + vzp0 * tau - 0.5 * self.g * tau * tau, vzp0 - self.g * tau
        dth = (y0[2] - self.th0) * math.exp(-self.rate * tau)
        om = -self.rate * dth
        th = self.th0 + dth
        s, c = math.sin(th), math.cos(th)
        return [xp - self.L * s, zp - self.L * c, th, vxp0 - self.L * om * c, vzp + self.L * om * s, om]

    def flight_step(self, t, y):
        vs = self.plate(t)[1]
        h = max(y[1] - self.plate(t)[0], 0.0)
        v = y[4] - vs
        dd = abs(y[2] - self.th0)
        a = self.g + self.d * self.w ** 2 + self.L * self.rate ** 2 * (dd * dd + dd)
        safe = (v + math.sqrt(v * v + 2 * a * h)) / a
        return min(max(safe, self.T / 256), 4 * self.T)

    def fly(self, t0, y0, t_end):
        hc = lambda t: self.flight_state(t0, y0, t)[1] - self.plate(t)[0]
        t = t0
        while True:
            y = self.flight_state(t0, y0, t)
            t1 = min(t + self.flight_step(t, y), t_end)
            if hc(t1) <= 0 and t1 > t:
                te = brentq(hc, t, t1, xtol=4e-16 * max(1, t1), rtol=8.9e-16)
                return te, self.flight_state(t0, y0, te), True
            if t1 >= t_end:
                return t1, self.flight_state(t0, y0, t1), False
            t = t1

    # ---- contact modes by solve_ivp
    def contact(self, mode, t0, y0, t_end, tol):
        def rhs(t, u):
            self.nfev += 1
            if mode == PIVOT:
                thdd, _, _, _ = self.pivot_eval(t, u[1], u[3])
                return [0.0, u[3], 0.0, thdd]
            thdd, xdd, _, _ = self.slide_eval(SIGMA[mode], t, u[1], u[3])
            return [u[2], u[3], xdd, thdd]

        def ev(fn, direction):
            fn.terminal, fn.direction = True, direction
            return fn
        if mode == PIVOT:
            evs = [ev(lambda t, u: self.pivot_eval(t, u[1], u[3])[3], -1),
                   ev(lambda t, u: (lambda e: self.mu * e[3] - e[2])(self.pivot_eval(t, u[1], u[3])), -1),
                   ev(lambda t, u: (lambda e: self.mu * e[3] + e[2])(self.pivot_eval(t, u[1], u[3])), -1),
                   ev(lambda t, u: math.cos(u[1]), -1)]
        else:
            sg = SIGMA[mode]
            evs = [ev(lambda t, u: self.den(sg, u[1]), 0),
                   ev(lambda t, u: self.torque(u[1], u[3]) * math.copysign(1.0, self.den(sg, u[1])), -1),
                   ev(lambda t, u: -sg * u[2], -1),
                   ev(lambda t, u: math.cos(u[1]), -1),
                   ev(lambda t, u: math.sin(u[1]), 0),
                   ev(lambda t, u: sg * u[2] - 1e-9, 1)]
        u0 = [y0[0], y0[2], y0[3], y0[5]]
        sol = solve_ivp(rhs, (t0, t_end), u0, method=self.method, rtol=tol, atol=tol, events=evs, max_step=self.T / 14)
        hits = [(te[0], i) for i, te in enumerate(sol.t_events) if len(te)]
        if not hits:
            if not sol.success:
                raise Invalid(sol.message)
            return sol.t[-1], self.full(sol.t[-1], sol.y[:, -1]), None
        te, i = min(hits)
        return te, self.full(te, sol.y_events[i][0]), i

    def transition(self, mode, i, t, y):
        if mode == PIVOT:
            if i == 3:
                raise Invalid("fell")
            return self.select_contact(t, y, allow_pivot=False)
        if i == 0:
            return self.jam(t, y)
        if i == 1:
            nxt = self.takeoff(t, y)
            if nxt is None:
                raise Invalid("inconsistent lift-off")
            return nxt
        if i == 2:
            return self.select_contact(t, y)
        raise Invalid("slide event %d" % i)

    def run(self, theta_start, cycles, tol):
        zs, vs, _ = self.plate(0.0)
        y = [0.0, zs, theta_start, 0.0, vs, 0.0]
        t, t_end = 0.0, cycles * self.T
        mode, y = self.select_contact(t, y)
        while t < t_end:
            if mode == FLIGHT:
                t, y, landed = self.fly(t, y, t_end)
                if landed:
                    mode, y = self.landing(t, y)
            else:
                t, y, i = self.contact(mode, t, y, t_end, tol)
                if i is not None:
                    mode, y = self.transition(mode, i, t, y)
        return y[0] / t_end


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--length-m", type=float, default=0.15)
    p.add_argument("--mass-kg", type=float, default=1.0)
    p.add_argument("--k", type=float, default=10.0, help="torsion stiffness (N m/rad)")
    p.add_argument("--gamma-damper", type=float, default=0.01, help="torsion damping (N m s/rad)")
    p.add_argument("--mu", type=float, default=0.4)
    p.add_argument("--theta0-rad", type=float, default=0.5 - 1.0 * 10.0 * 0.15 * math.sin(0.5) / 10.0)
    p.add_argument("--theta-start-rad", type=float, default=0.5, help="static angle (rad)")
    p.add_argument("--g-mps2", type=float, default=10.0)
    p.add_argument("--gamma", type=float, default=10.0, help="peak plate acceleration over g")
    p.add_argument("--frequency-hz", type=float, default=30.0)
    p.add_argument("--cycles", type=float, default=50.0)
    p.add_argument("--tol", type=float, default=1e-10, help="rtol = atol")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--method", default="RK45", help="solve_ivp method (RK45, DOP853, ...)")
    a = p.parse_args()
    best, v, nfev, hops = math.inf, float("nan"), 0, 0
    for _ in range(max(1, a.repeats)):
        s = Stick(a)
        t0 = time.perf_counter()
        try:
            v = s.run(a.theta_start_rad, a.cycles, a.tol)
        except Invalid as e:
            print(json.dumps({"error": str(e)}))
            return
        best = min(best, time.perf_counter() - t0)
        nfev, hops = s.nfev, s.hops
    print(json.dumps({"mean_velocity_mps": v, "wall_s": best, "rhs_evals": nfev, "landings": hops}))


if __name__ == "__main__":
    main()
