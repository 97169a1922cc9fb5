//! What a figure can draw: labels without control characters, axis ranges the plotting backend
//! can tick, and tick labels of round numbers on a log axis.
//!
//! ```text
//! drawable range:  lo, hi finite,  hi > lo,  max(|lo|, |hi|) ≤ 1e150,  hi − lo ≥ 1e-150
//! axis range:      [lo − 5 % span, hi + 5 % span]   (log axis: [lo / r, hi · r], r = (hi/lo)^0.05)
//! log tick label:  three significant digits; plain from 0.001 to 99999, m·e±k outside
//! ```

/// `text` with every control character (C0, DEL, C1; tab and line breaks included, which a
/// one-line label cannot show) and the non-characters U+FFFE, U+FFFF replaced by U+FFFD, so that
/// it can go into any figure: XML 1.0, and so SVG, allows no C0 control but tab and line breaks.
pub fn drawable_text(text: &str) -> String {
    text.chars().map(|c| if c.is_control() || c == '\u{FFFE}' || c == '\u{FFFF}' { '\u{FFFD}' } else { c }).collect()
}

/// The largest magnitude an axis may reach and the smallest range it may span: the plotting
/// backend computes tick positions by repeated steps of 10^⌊log10(range)⌋, which overflow,
/// underflow to subnormals or never end outside these bounds.
pub const DRAWABLE_MAGNITUDE: (f64, f64) = (1e-150, 1e150);

/// Checks that an axis range `lo..hi` can be drawn: finite, `hi > lo`, within
/// [`DRAWABLE_MAGNITUDE`] (|lo|, |hi| ≤ 1e150 and hi − lo ≥ 1e-150).
///
/// # Errors
/// Why the range cannot be drawn, for a note in place of the figure.
pub fn drawable_range(lo: f64, hi: f64) -> Result<(), String> {
    let (small, large) = DRAWABLE_MAGNITUDE;
    if !(lo.is_finite() && hi.is_finite()) {
        return Err(format!("non-finite range [{lo}, {hi}]"));
    }
    if hi <= lo {
        return Err(format!("zero range at {lo}"));
    }
    if lo.abs().max(hi.abs()) > large {
        return Err(format!("values up to {:.3e} exceed ±{large:e}", lo.abs().max(hi.abs())));
    }
    if hi - lo < small {
        return Err(format!("range {:.3e} is below {small:e}", hi - lo));
    }
    Ok(())
}

/// The range of an axis over the finite values (positive ones on a log axis), with a margin.
pub(crate) fn axis_range(values: impl Iterator<Item = f64>, log: bool) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && (!log || *v > 0.0))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if !lo.is_finite() {
        return if log { (0.1, 10.0) } else { (0.0, 1.0) };
    }
    if log {
        // A 5 % margin in log space.
        let pad = if hi / lo < 1.0 + 1e-9 { 2.0 } else { (hi / lo).powf(0.05) };
        (lo / pad, hi * pad)
    } else {
        let span = hi - lo;
        if span <= 1e-12 * hi.abs().max(lo.abs()).max(1e-300) {
            let pad = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
            (lo - pad, hi + pad)
        } else {
            (lo - 0.05 * span, hi + 0.05 * span)
        }
    }
}

/// The label of a tick on a log axis: the value to three significant digits, as plain decimals
/// from 0.001 to 99999 and as `<mantissa>e<exponent>` outside (1e-5, 2.5e-7, 1e6); trailing
/// zeros dropped. The backend's tick values carry round-off (9.999999998e-6), which this removes.
pub fn log_tick_label(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return format!("{v}");
    }
    let rounded: f64 = format!("{v:.2e}").parse().unwrap_or(v);
    let exponent = rounded.abs().log10().floor() as i32;
    if (-3..=4).contains(&exponent) {
        let decimals = (2 - exponent).max(0) as usize;
        trim_zeros(&format!("{rounded:.decimals$}"))
    } else {
        let text = format!("{rounded:.2e}");
        let (mantissa, exp) = text.split_once('e').unwrap_or((&text, "0"));
        format!("{}e{exp}", trim_zeros(mantissa))
    }
}

/// `text` without the trailing zeros of its decimals (and without a trailing point).
fn trim_zeros(text: &str) -> String {
    if text.contains('.') { text.trim_end_matches('0').trim_end_matches('.').to_string() } else { text.to_string() }
}

#[cfg(test)]
#[allow(clippy::unwrap_used)]
mod tests {
    use super::*;
    use plotters::prelude::{IntoLogRange, LogCoord};

    #[test]
    fn log_ticks_are_round_numbers() {
        use plotters::coord::ranged1d::Ranged;
        // The issue's case: the backend's key points on [9.99e-6, 1.2e-3] carry round-off
        // (9.999999998e-6 printed "9999999998e-5"); each label must read back to its value
        // within that round-off (1e-9 relative) and have at most three significant digits.
        for (lo, hi) in [(9.99e-6, 1.2e-3), (0.03, 700.0), (2e-9, 3e-8)] {
            // With line_chart's margin.
            let (lo, hi) = axis_range([lo, hi].into_iter(), true);
            let coord: LogCoord<f64> = (lo..hi).log_scale().into();
            let ticks = coord.key_points(12);
            assert!(!ticks.is_empty(), "[{lo}, {hi}]");
            for v in ticks {
                let label = log_tick_label(v);
                let back: f64 = label.parse().unwrap();
                assert!((back / v - 1.0).abs() < 5e-3, "{v} labelled {label}");
                let digits: String = label.split('e').next().unwrap().chars().filter(char::is_ascii_digit).collect();
                assert!(digits.trim_matches('0').len() <= 3, "{v} labelled {label}");
            }
        }
        // Worked values (the expected texts are the definition: three significant digits,
        // plain from 0.001 to 99999, exponent form outside).
        let cases = [(9.999999998e-6, "1e-5"), (1e-4, "1e-4"), (0.0010000000002, "0.001"), (2.5e-7, "2.5e-7")];
        for (v, text) in cases.into_iter().chain([(120.0, "120"), (0.0199999, "0.02"), (1e6, "1e6")]) {
            assert_eq!(log_tick_label(v), text);
        }
    }

    #[test]
    fn axis_range_covers_the_data() {
        assert_eq!(axis_range([0.0, 10.0].into_iter(), false), (-0.5, 10.5));
        let (lo, hi) = axis_range([1e-2, 1e2, -3.0].into_iter(), true);
        assert!((lo * 10f64.powf(0.2) - 1e-2).abs() < 1e-12 && (hi / 10f64.powf(0.2) - 1e2).abs() < 1e-9);
        assert_eq!(axis_range(std::iter::empty(), false), (0.0, 1.0));
        let (lo, hi) = axis_range([2.0, 2.0].into_iter(), false);
        assert!(lo < 2.0 && hi > 2.0);
    }
}
