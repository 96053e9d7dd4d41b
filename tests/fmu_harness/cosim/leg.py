"""A landing-gear leg for the co-simulation scenes: a rigid body of inertia J on the pin,
J dw/dt = drive(t) + drive_input + torque, integrated by symplectic Euler over each
communication step with its inputs held (w <- w + h a, angle <- angle + h w). Built into
Leg.fmu (FMI 2.0 Co-Simulation) by pythonfmu in the test run (`pythonfmu build -f leg.py`).

The drive is a schedule of three torques: `drive_hold` until `t_ramp`, a ramp to
`drive_peak` by `t_peak`, `drive_peak` until `t_release`, then `drive_rest`; plus the input
`drive_input`. Outputs: `angle` (rad), `angular_velocity` (rad/s), `drive` (N.m)."""

from pythonfmu import Fmi2Causality, Fmi2Slave, Fmi2Variability, Real


class Leg(Fmi2Slave):
    author = "pinjoint"
    description = "Rigid landing-gear leg on a pin joint: J dw/dt = drive + torque, symplectic Euler"

    def __init__(self, **kwargs):
        super().__init__(**kwargs)
        self.inertia = 20.0
        self.drive_hold = 0.0
        self.drive_peak = 0.0
        self.drive_rest = 0.0
        self.t_ramp = 1e9
        self.t_peak = 1e9
        self.t_release = 1e9
        self.angle = 0.0
        self.angular_velocity = 0.0
        self.torque = 0.0
        self.drive_input = 0.0
        self.drive = 0.0
        parameter = dict(causality=Fmi2Causality.parameter, variability=Fmi2Variability.tunable)
        for name in ("inertia", "drive_hold", "drive_peak", "drive_rest", "t_ramp", "t_peak", "t_release"):
            self.register_variable(Real(name, **parameter))
        for name in ("torque", "drive_input"):
            self.register_variable(Real(name, causality=Fmi2Causality.input))
        for name in ("angle", "angular_velocity", "drive"):
            self.register_variable(Real(name, causality=Fmi2Causality.output))

    def schedule(self, t):
        if t < self.t_ramp:
            return self.drive_hold
        if t < self.t_peak:
            return self.drive_hold + (self.drive_peak - self.drive_hold) * (t - self.t_ramp) / (self.t_peak - self.t_ramp)
        if t < self.t_release:
            return self.drive_peak
        return self.drive_rest

    def do_step(self, current_time, step_size):
        self.drive = self.schedule(current_time) + self.drive_input
        self.angular_velocity += step_size * (self.drive + self.torque) / self.inertia
        self.angle += step_size * self.angular_velocity
        return True
