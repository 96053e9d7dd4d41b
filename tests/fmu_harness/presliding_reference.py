"""A small Python reference of the single-state elasto-plastic (presliding) zero-velocity
law of PinJoint (Dupont, Hayward, Armstrong, Altpeter, "Single state elastoplastic friction
models", IEEE TAC 47(5), 2002), written independently of the Rust implementation, so that
the host-inertia scenes of scene_host.py can be run and their thresholds validated without
the FMU. The Rust law in the core library is authoritative; this one uses the low-speed
sliding bound T = mu_c R |P| at every speed (no speed dependence).

State: tau (N.m), the elastic presliding torque (its sign is that of the deflection).
Along a deflection increment dD with direction s = sign(dD), u = s tau obeys
    du/dD = k                            for u <= tau_ba = beta T   (elastic),
    du/dD = k (T - u) / (T - tau_ba)     above                      (plastic),
with k = T / phi_s. Over a finite increment this is solved exactly (elastic up to tau_ba,
then T - u decays as exp(-k D / (T - tau_ba))), so the update is bounded for any increment.
Output torque = -(clamp(tau, -T, T) + t_d (dtau/dD) omega)  (c = k t_d, z' = (dtau/dD)/k omega).

Two front ends with the interfaces scene_host.py drives:
- ReferenceCoSim: the Co-Simulation behaviour (state driven by the angle input's increments
  between communication points, by omega h if the angle is not set during a step);
- ReferenceModelExchange: the continuous state and its derivative for an ODE solver.
BandReference is today's stateless band law (-T omega / band inside the band) for comparison.
"""

import math

MU_C = 0.12      # friction.boundary_friction_coefficient
RADIUS = 0.028   # m, geometry.pin_radius


def static_torque(load, mu_c=MU_C, radius=RADIUS):
    """T_s = mu_c R |P| (N.m) for the load P (N)."""
    return mu_c * radius * abs(load)


class PreslidingLaw:
    """The law's parameters and its exact increment: phi_s (rad, presliding angle at
    breakaway), beta (1, elastic limit as a fraction of T), t_d (s, damping time)."""

    def __init__(self, presliding_angle=1.5e-3, elastic_limit=0.95, damping_time=0.01, mu_c=MU_C, radius=RADIUS,
                 damping_coefficient=None):
        for name, value in (("presliding_angle", presliding_angle), ("elastic_limit", elastic_limit),
                            ("damping_time", damping_time)):
            if not (value >= 0 and math.isfinite(value)):
                raise ValueError(f"zero_velocity.{name} = {value!r} must be finite and >= 0")
        if presliding_angle <= 0:
            raise ValueError(f"zero_velocity.presliding_angle = {presliding_angle!r} rad must be > 0")
        if elastic_limit > 1:
            raise ValueError(f"zero_velocity.elastic_limit = {elastic_limit!r} must be <= 1")
        self.phi_s, self.beta, self.t_d = presliding_angle, elastic_limit, damping_time
        self.mu_c, self.radius = mu_c, radius
        # an alternative studied for the lead: a load-independent damping coefficient c0
        # (N.m.s/rad) instead of c = k t_d (the damping torque is then c0 z', z' = (dtau/dD)/k w)
        self.c0 = damping_coefficient

    def bound(self, load):
        """The sliding bound T (N.m) at load P (N)."""
        return static_torque(load, self.mu_c, self.radius)

    def advance(self, tau, d, T):
        """tau after a deflection increment d (rad) at bound T (exact, bounded for any d)."""
        if T <= 0:
            return 0.0
        if d == 0:
            return tau
        s = 1.0 if d > 0 else -1.0
        u, a = s * tau, abs(d)
        k = T / self.phi_s
        tb = self.beta * T
        if u < tb:
            de = (tb - u) / k
            if a <= de:
                return s * (u + k * a)
            a -= de
            u = tb
        span = T - tb
        if span <= 0:
            return s * T
        return s * (T - (T - u) * math.exp(-k * a / span))

    def slope(self, tau, s, T):
        """dtau/dD (N.m/rad) at tau along direction s (+1 or -1)."""
        if T <= 0:
            return 0.0
        k = T / self.phi_s
        u = s * tau
        tb = self.beta * T
        if u <= tb:
            return k
        span = T - tb
        return k * (T - u) / span if span > 0 else 0.0

    def torque(self, tau, omega, T):
        """Output torque (N.m) at state tau, speed omega, bound T."""
        s = 1.0 if omega >= 0 else -1.0
        return -(min(max(tau, -T), T) + self.damping_time(T) * self.slope(tau, s, T) * omega)

    def damping_time(self, T):
        """c / k (s): t_d, or c0 / k with the load-independent coefficient."""
        if self.c0 is None or T <= 0:
            return self.t_d
        return self.c0 * self.phi_s / T


class ReferenceCoSim:
    """The Co-Simulation front end (same methods as scene_host.CoSimJoint)."""

    provides_partials = True

    def __init__(self, law=None, angle=0.0, tau=0.0):
        self.law = law or PreslidingLaw()
        self.theta_c, self.tau_c = angle, tau
        self.theta, self.omega, self.load = angle, 0.0, 0.0
        self.angle_set = False
        self.tau = tau

    def set_inputs(self, theta, omega, load):
        self.theta, self.omega, self.load = theta, omega, load
        self.angle_set = True
        self.tau = self.law.advance(self.tau_c, theta - self.theta_c, self.law.bound(load))

    def torque(self):
        return self.law.torque(self.tau, self.omega, self.law.bound(self.load))

    def do_step(self, t, h):
        if self.angle_set:
            self.theta_c, self.tau_c = self.theta, self.tau
        else:
            d = self.omega * h
            self.tau_c = self.law.advance(self.tau_c, d, self.law.bound(self.load))
            self.theta_c += d
            self.tau = self.tau_c
        self.angle_set = False

    def partials(self):
        """(d torque/d angle, d torque/d angular_velocity) at the current inputs; the angle
        tangent is one-sided, taken in the direction of the angular_velocity input (the
        motion about to happen; a host predicting a reversal sets w to the predicted value
        and asks again), else of the last angle increment, else the elastic one."""
        T = self.law.bound(self.load)
        d = self.theta - self.theta_c
        s = math.copysign(1.0, self.omega) if self.omega != 0 else (
            math.copysign(1.0, d) if d != 0 else (-1.0 if self.tau > 0 else 1.0))
        sl = self.law.slope(self.tau, s, T)
        sw = 1.0 if self.omega >= 0 else -1.0
        return -sl, -self.law.damping_time(T) * self.law.slope(self.tau, sw, T)

    def close(self):
        pass


class ReferenceModelExchange:
    """The Model Exchange front end (same methods as scene_host.MEJoint): one state tau."""

    n_states = 1
    provides_partials = True

    def __init__(self, law=None):
        self.law = law or PreslidingLaw()

    def evaluate(self, t, theta, omega, load, x):
        """(torque, [dtau/dt]) at the state x = [tau]."""
        T = self.law.bound(load)
        tau = x[0]
        s = 1.0 if omega >= 0 else -1.0
        dtau = self.law.slope(tau, s, T) * omega
        return -(min(max(tau, -T), T) + self.law.damping_time(T) * dtau), [dtau]

    def partials(self, t, theta, omega, load, x):
        """d torque/d omega, d torque/d x (list), d xdot/d omega (list), d xdot/d x (matrix)."""
        T = self.law.bound(load)
        tau = x[0]
        s = 1.0 if omega >= 0 else -1.0
        sl = self.law.slope(tau, s, T)
        tb = self.law.beta * T
        span = T - tb
        plastic = s * tau > tb and span > 0
        k = T / self.law.phi_s if T > 0 else 0.0
        dd_tau = -k * abs(omega) / span if plastic else 0.0
        inside = 1.0 if abs(tau) < T else 0.0
        td = self.law.damping_time(T)
        return (-td * sl, [-(inside + td * dd_tau)], [sl], [[dd_tau]])

    def completed_step(self):
        pass

    def close(self):
        pass


class BandReference:
    """Today's stateless band law, T = mu_c R |P| (Co-Simulation front end, no state)."""

    provides_partials = True

    def __init__(self, band=0.01, mu_c=MU_C, radius=RADIUS):
        self.band, self.mu_c, self.radius = band, mu_c, radius
        self.omega, self.load = 0.0, 0.0

    def set_inputs(self, theta, omega, load):
        self.omega, self.load = omega, load

    def torque(self):
        T = static_torque(self.load, self.mu_c, self.radius)
        if abs(self.omega) < self.band:
            return -T * self.omega / self.band
        return -math.copysign(T, self.omega)

    def do_step(self, t, h):
        pass

    def partials(self):
        T = static_torque(self.load, self.mu_c, self.radius)
        return 0.0, (-T / self.band if abs(self.omega) < self.band else 0.0)

    def close(self):
        pass
