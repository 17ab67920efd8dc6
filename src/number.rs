//! Numbers as the control reads them: fixed point, never an exponent. A
//! leaf: the rewrite, the model's texts and the reports all print numbers so.

/// `value` rounded to `precision` decimals, trailing zeros and a trailing
/// point removed; `-0` prints as `0`. Rounding moves the value by at most
/// half a unit of the last printed digit.
pub fn format(value: f64, precision: usize) -> String {
    let mut text = std::format!("{value:.precision$}");
    if text.contains('.') {
        let trimmed = text.trim_end_matches('0').trim_end_matches('.').len();
        text.truncate(trimmed);
    }
    if text == "-0" {
        text = "0".to_string();
    }
    text
}

#[cfg(test)]
mod tests {
    use super::format;

    #[test]
    fn fixed_point_trimmed_and_no_negative_zero() {
        assert_eq!(format(37.79234567, 6), "37.792346");
        assert_eq!(format(30.0, 6), "30");
        assert_eq!(format(-0.0000001, 6), "0");
        assert_eq!(format(-16.2799062, 4), "-16.2799");
        assert_eq!(format(1e20, 3), "100000000000000000000");
        assert_eq!(format(1.5e-7, 6), "0");
        assert_eq!(format(0.1, 0), "0");
    }
}
