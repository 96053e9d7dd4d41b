//! Error messages for Python: the library's texts, with every value in its shortest
//! round-trip form (`1e308`, never 309 digits) and the array index of the failing point.

use pinjoint::ModelError;

/// A number as the shortest text that reads back as the same f64 (Python's `repr`).
pub fn short(v: f64) -> String {
    format!("{v:?}")
}

/// `"at index 3"`, `"at index (1, 2)"` (C order in `shape`), or `""` for a 0-d input.
pub fn index_text(flat: usize, shape: &[usize]) -> String {
    match shape.len() {
        0 => String::new(),
        1 => format!("at index {flat}"),
        _ => {
            let mut rest = flat;
            let mut idx = vec![0usize; shape.len()];
            for (k, &n) in shape.iter().enumerate().rev() {
                let n = n.max(1);
                idx[k] = rest % n;
                rest /= n;
            }
            let parts: Vec<String> = idx.iter().map(usize::to_string).collect();
            format!("at index ({})", parts.join(", "))
        }
    }
}

/// The library's message for a rejected operating point, values in short form. The input
/// `speed` is the angular velocity ω of the library.
pub fn model_error(e: &ModelError) -> String {
    #[allow(unreachable_patterns)]
    match e {
        ModelError::Load(v) => format!("load = {} N is invalid: the load must be a finite number > 0 N", short(*v)),
        ModelError::Speed(v) => format!("speed = {} rad/s is invalid: the angular velocity must be a finite number", short(*v)),
        ModelError::BeyondCapacity { load, capacity } => format!(
            "load = {} N is beyond the asperity model's capacity of {capacity:.6e} N for these parameters: \
             at rest eq. 19 would put the mean planes of the surfaces through each other (h_c <= 0)",
            short(*load)
        ),
        ModelError::NotFinite { quantity, value, load, omega } => format!(
            "the model gives {quantity} = {} at load = {} N, speed = {} rad/s: outside its numerical range for these parameters",
            short(*value),
            short(*load),
            short(*omega)
        ),
        other => other.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_is_unravelled_in_c_order() {
        assert_eq!(index_text(5, &[2, 3]), "at index (1, 2)");
        assert_eq!(index_text(7, &[10]), "at index 7");
        assert_eq!(index_text(0, &[]), "");
        assert_eq!(index_text(23, &[2, 3, 4]), "at index (1, 2, 3)");
    }

    #[test]
    fn values_are_short() {
        assert_eq!(model_error(&ModelError::Load(1e308)), "load = 1e308 N is invalid: the load must be a finite number > 0 N");
        assert!(model_error(&ModelError::Speed(f64::NAN)).contains("speed = NaN rad/s"));
    }
}
