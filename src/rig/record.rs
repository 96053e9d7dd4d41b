//! The one record of a rig sample: the columns of `cycle.csv` (the CLI) and of
//! `pinjoint.simulate_cycle` (the Python package), in one order, with their SI units.

use super::sim::Sample;

/// One numeric column of a sample: name, SI unit, accessor.
pub type NumericColumn = (&'static str, &'static str, fn(&Sample) -> f64);

/// The numeric columns of a sample. `stuck` follows them (see [`COLUMNS`]).
pub const NUMERIC_COLUMNS: [NumericColumn; 9] = [
    ("time", "s", |s| s.time),
    ("command_angle", "rad", |s| s.command_angle),
    ("angle", "rad", |s| s.angle),
    ("angular_velocity", "rad/s", |s| s.angular_velocity),
    ("torque", "N.m", |s| s.torque),
    ("friction_torque", "N.m", |s| s.friction_torque),
    ("friction_coefficient", "1", |s| s.friction_coefficient),
    ("film_thickness", "m", |s| s.film_thickness),
    ("fluid_load_fraction", "1", |s| s.fluid_load_fraction),
];

/// Every column of a sample, in order: [`NUMERIC_COLUMNS`], then `stuck` (a Boolean: 0/1 in
/// CSV).
pub const COLUMNS: [&str; 10] = {
    let mut names = [""; 10];
    let mut i = 0;
    while i < NUMERIC_COLUMNS.len() {
        names[i] = NUMERIC_COLUMNS[i].0;
        i += 1;
    }
    names[9] = "stuck";
    names
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_read_their_own_fields() {
        let s = Sample {
            time: 1.0,
            command_angle: 2.0,
            angle: 3.0,
            angular_velocity: 4.0,
            torque: 5.0,
            friction_torque: 6.0,
            friction_coefficient: 7.0,
            film_thickness: 8.0,
            fluid_load_fraction: 9.0,
            stuck: true,
            load: 10.0,
            actuator_work: 11.0,
            friction_dissipation: 12.0,
            kinetic_energy: 13.0,
        };
        let values: Vec<f64> = NUMERIC_COLUMNS.iter().map(|(_, _, f)| f(&s)).collect();
        assert_eq!(values, [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]);
        assert_eq!(COLUMNS[9], "stuck");
    }
}
