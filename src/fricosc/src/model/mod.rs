//! The model: checked results ([`ratio::Ratio`]) and one spring ([`spring`]).
pub mod ratio;
pub mod spring;
pub mod stop;

use crate::error::{Error, Result};

/// `vbar` (eq. 3) from the velocity `vhat = vbar amp` (eq. 15), which the seed
/// uses for its jumping amplitudes: `vhat / amp`, refused where `amp` is 0 (the
/// velocity has no `vbar` then) or the quotient overflows.
///
/// ```
/// assert_eq!(fricosc::vbar_from_vhat(0.3, 2.0)?, 0.15);
/// assert!(fricosc::vbar_from_vhat(0.3, 0.0).is_err());
/// # Ok::<(), fricosc::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for a negative or non-finite input, `amp = 0`, or an overflow.
pub fn vbar_from_vhat(vhat: f64, amp: f64) -> Result<f64> {
    crate::error::check_nonneg("vhat", vhat)?;
    crate::error::check_nonneg("amp", amp)?;
    if amp > 0.0 {
        let vbar = vhat / amp;
        if vbar.is_finite() {
            Ok(vbar)
        } else {
            Err(Error::param("vbar", vbar, &format!("vhat / amp = {vhat:?} / {amp:?} overflows double precision")))
        }
    } else {
        Err(Error::param("amp", amp, "vhat needs amp > 0 (vbar = vhat / amp)"))
    }
}

#[cfg(test)]
mod tests {
    /// `amp = 0` is refused as such (not as an overflow of `vhat / 0`), with
    /// `vhat` zero or not.
    #[test]
    fn vbar_from_vhat_refuses_a_zero_amplitude_by_name() {
        for vhat in [0.0, 0.3] {
            let e = super::vbar_from_vhat(vhat, 0.0).unwrap_err().to_string();
            assert!(e.contains("needs amp > 0") && !e.contains("overflows"), "{e}");
        }
        let e = super::vbar_from_vhat(1e300, 1e-300).unwrap_err().to_string();
        assert!(e.contains("overflows"), "{e}");
        assert_eq!(super::vbar_from_vhat(0.0, 5e-324).unwrap(), 0.0);
    }
}
