//! Numbers in reprs and messages, printed the way Python's `%.6g` prints them.

/// A number the way Python's `%.6g` prints it.
pub fn g(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{}", if x == 0.0 { 0.0 } else { x });
    }
    let exponent = x.abs().log10().floor() as i32;
    let trim = |s: String| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    };
    if (-5..6).contains(&exponent) {
        trim(format!("{:.*}", (5 - exponent).max(0) as usize, x))
    } else {
        let s = format!("{x:.5e}");
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        format!("{}e{exp}", trim(mantissa.to_string()))
    }
}

/// `[a, b, c]` with `%.6g` numbers.
pub fn g3(v: &[f64; 3]) -> String {
    format!("[{}, {}, {}]", g(v[0]), g(v[1]), g(v[2]))
}
