//! Parsing of value lists on the command line: `0,0.2,0.4` or `start:stop:count`.

use crate::error::{Error, Result};

/// Most values one list or range may produce.
pub const MAX_LIST: u128 = 10_000_000;

/// Parse one finite number; `what` names it in the error.
pub fn parse_number(what: &str, text: &str) -> Result<f64> {
    let t = text.trim();
    let x: f64 =
        t.parse().map_err(|_| Error::Parse { context: what.into(), reason: format!("'{t}' is not a number") })?;
    if !x.is_finite() {
        return Err(Error::Parse { context: what.into(), reason: format!("'{t}' is not finite") });
    }
    // -0.0 is 0 (it would print back as -0.0 in vbar and reduction).
    Ok(x + 0.0)
}

/// A comma list `a,b,c` or an inclusive range `start:stop:count` (`count >= 1`,
/// `stop >= start`; `count = 1` gives `start`). Values are
/// `start + (stop - start) k / (count - 1)` rounded to 15 significant digits (so
/// `0:1.2:13` gives 0.1, 0.2, ... rather than 0.09999999999999999), the last one
/// `stop` exactly; outputs print the value actually used.
pub fn parse_values(what: &str, text: &str) -> Result<Vec<f64>> {
    let t = text.trim();
    if t.is_empty() {
        return Err(Error::Parse { context: what.into(), reason: "empty value list".into() });
    }
    let parts: Vec<&str> = t.split(':').collect();
    match parts.len() {
        1 => t.split(',').map(|p| parse_number(what, p)).collect(),
        3 => {
            let start = parse_number(what, parts[0])?;
            let stop = parse_number(what, parts[1])?;
            let c = parts[2].trim();
            let count: u128 = c.parse().map_err(|_| Error::Parse {
                context: what.into(),
                reason: format!("range count '{c}' is not a whole number"),
            })?;
            if count == 0 {
                return Err(Error::Parse { context: what.into(), reason: "range count must be >= 1".into() });
            }
            if count > MAX_LIST {
                return Err(Error::TooLarge { what: format!("{what} range count"), count, limit: MAX_LIST });
            }
            if stop < start {
                return Err(Error::Parse {
                    context: what.into(),
                    reason: format!("range stop {stop:?} is below start {start:?}"),
                });
            }
            let n = count as usize;
            if n == 1 {
                return Ok(vec![start]);
            }
            let span = stop - start;
            let last = (n - 1) as f64;
            Ok((0..n).map(|k| if k + 1 == n { stop } else { decimal(start + span * k as f64 / last) }).collect())
        }
        _ => Err(Error::Parse {
            context: what.into(),
            reason: format!("'{t}' is neither a comma list nor start:stop:count"),
        }),
    }
}

/// Round to 15 significant digits: removes the binary noise of `k * step`.
fn decimal(x: f64) -> f64 {
    format!("{x:.14e}").parse().unwrap_or(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_and_ranges() {
        assert_eq!(parse_values("v", "0, 0.2,0.4").unwrap(), vec![0.0, 0.2, 0.4]);
        let r = parse_values("v", "0:1.2:121").unwrap();
        assert_eq!(r.len(), 121);
        assert_eq!(r[120], 1.2);
        assert_eq!(r[60], 0.6);
        assert_eq!(parse_values("v", "0:1.2:13").unwrap()[1], 0.1);
        assert_eq!(parse_values("v", "0.5:0.5:1").unwrap(), vec![0.5]);
        for bad in ["", "a", "nan", "inf", "1e999", "1:0:3", "0:1:0", "0:1:x", "0:1", "0:1:1000000000000"] {
            assert!(parse_values("v", bad).is_err(), "{bad}");
        }
    }
}
