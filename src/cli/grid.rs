//! Parsing of value lists on the command line: `0,0.2,0.4` or `start:stop:count`.

/// Most rows any command reads or writes (tables, batches, validated tables,
/// histories), and most values one list or range may produce: the one limit.
pub const MAX_ROWS: usize = fricosc::history::MAX_SAMPLES;
/// [`MAX_ROWS`] for counts computed in `u128` (before they can overflow).
pub const MAX_LIST: u128 = MAX_ROWS as u128;

/// One finite number (`-0` is 0), or why not: the value parser of every
/// numeric option.
pub fn number(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let x: f64 = t.parse().map_err(|_| format!("'{t}' is not a number"))?;
    if !x.is_finite() {
        return Err(format!("'{t}' is not finite"));
    }
    // -0.0 is 0 (it would print back as -0.0 in vbar and reduction).
    Ok(x + 0.0)
}

/// A comma list `a,b,c` or an inclusive range `start:stop:count` (`count >= 1`,
/// `stop >= start`; `count = 1` gives `start`), or why not. Values are
/// `start + (stop - start) k / (count - 1)` rounded to 15 significant digits (so
/// `0:1.2:13` gives 0.1, 0.2, ... rather than 0.09999999999999999), the last one
/// `stop` exactly; outputs print the value actually used. At most [`MAX_ROWS`] values.
pub fn values(text: &str) -> Result<Vec<f64>, String> {
    let t = text.trim();
    if t.is_empty() {
        return Err("empty value list".into());
    }
    let parts: Vec<&str> = t.split(':').collect();
    match parts.len() {
        1 => {
            let n = t.split(',').count();
            if n as u128 > MAX_LIST {
                return Err(format!("list of {n} values: more than the limit of {MAX_LIST}"));
            }
            t.split(',').map(number).collect()
        }
        3 => range(number(parts[0])?, number(parts[1])?, parts[2].trim()),
        _ => Err(format!("'{t}' is neither a comma list nor start:stop:count")),
    }
}

/// The range `start:stop:count` of [`values`].
fn range(start: f64, stop: f64, count: &str) -> Result<Vec<f64>, String> {
    let count: u128 = count.parse().map_err(|_| format!("range count '{count}' is not a whole number"))?;
    if count == 0 {
        return Err("range count must be >= 1".into());
    }
    if count > MAX_LIST {
        return Err(format!("range count: {count} is more than the limit of {MAX_LIST}"));
    }
    if stop < start {
        return Err(format!("range stop {stop:?} is below start {start:?}"));
    }
    let n = count as usize;
    if n == 1 {
        return Ok(vec![start]);
    }
    let out = fricosc::spaced(start, stop, n, false);
    if let Some(w) = out.windows(2).find(|w| w[1] <= w[0]) {
        return Err(format!(
            "the range {start:?}:{stop:?} holds fewer than {n} distinct double values ({:?} repeats)",
            w[1]
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_and_ranges() {
        assert_eq!(values("0, 0.2,0.4").unwrap(), vec![0.0, 0.2, 0.4]);
        let r = values("0:1.2:121").unwrap();
        assert_eq!(r.len(), 121);
        assert_eq!(r[120], 1.2);
        assert_eq!(r[60], 0.6);
        assert_eq!(values("0:1.2:13").unwrap()[1], 0.1);
        assert_eq!(values("0.5:0.5:1").unwrap(), vec![0.5]);
        // Rounding never leaves [start, stop] nor repeats a value; a range too
        // narrow for its count is an error, a range across f64 is not NaN.
        assert_eq!(
            values("0.9999999999999998:0.9999999999999999:2").unwrap(),
            vec![0.9999999999999998, 0.9999999999999999]
        );
        assert!(values("0.9999999999999998:0.9999999999999999:3").is_err());
        assert!(values("0.999999999999999:1:11").is_err());
        assert_eq!(values("-1e308:1e308:3").unwrap(), vec![-1e308, 0.0, 1e308]);
        let r = values("0.1:0.7:7").unwrap();
        assert_eq!(r, vec![0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]);
        for bad in ["", "a", "nan", "inf", "1e999", "1:0:3", "0:1:0", "0:1:x", "0:1", "0:1:1000000000000"] {
            assert!(values(bad).is_err(), "{bad}");
        }
    }
}
