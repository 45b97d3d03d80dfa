//! A scene's oscillations in the plane: checked in SI units, in pre-slip
//! lengths `l = mu0 u_z0 kz/kx = mu0 u_z0 E*/G*` per amplitude, and the
//! conditions of one row with them.

use super::solve::{field, Checked};
use super::Scene;
use crate::error::{Error, Result};

/// The oscillations in the plane of a scene, checked: each amplitude finite
/// and `>= 0` (0 is none), each phase finite; across the sliding direction
/// not on a system.
pub(super) type InPlane = (Option<(f64, f64)>, Option<(f64, f64)>);
pub(super) fn in_plane(s: &Scene, source: &str) -> Result<InPlane> {
    let o = &s.oscillation;
    let one = |amp: Option<f64>, phase: f64, names: (&str, &str)| -> Result<Option<(f64, f64)>> {
        let Some(a) = amp else { return Ok(None) };
        let a = field(source, names.0, a, a >= 0.0, "must be finite and >= 0")?;
        let phase = field(source, names.1, phase, true, "must be finite")?;
        Ok((a > 0.0).then_some((a, phase)))
    };
    let tangential = one(
        o.tangential_amplitude_m,
        o.tangential_phase_rad,
        ("oscillation.tangential_amplitude_m", "oscillation.tangential_phase_rad"),
    )?;
    let transverse = one(
        o.transverse_amplitude_m,
        o.transverse_phase_rad,
        ("oscillation.transverse_amplitude_m", "oscillation.transverse_phase_rad"),
    )?;
    if transverse.is_some() && s.system.is_some() {
        return Err(Error::Parse {
            context: format!("{source}: oscillation.transverse_amplitude_m"),
            reason: "with a system: a body on a system is not solved in the plane yet".into(),
        });
    }
    Ok((tangential, transverse))
}

/// A scene's oscillations in the plane for one amplitude, in pre-slip lengths:
/// `(T, phase)` along the sliding direction (the phase reduced to `[0, 2 pi)`)
/// and the drive across it.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct Drives {
    pub(super) tangential: Option<(f64, f64)>,
    pub(super) transverse: Option<crate::plane::Transverse>,
}

impl Drives {
    /// Whether there is an oscillation in the plane.
    pub(super) fn any(&self) -> bool {
        self.tangential.is_some() || self.transverse.is_some()
    }

    /// The conditions of one row at `vbar` (eq. 3) and `amp`: the seed's
    /// problem, or with the drives the same velocity as `vhat = vbar amp`
    /// (eq. 15).
    pub(super) fn conditions(&self, vbar: f64, amp: f64) -> Result<crate::Conditions> {
        if !self.any() {
            return crate::Conditions::vbar(vbar, amp);
        }
        let mut c = crate::Conditions::vhat(vbar * amp, amp)?;
        if let Some((t, phase)) = self.tangential {
            c = c.with_tangential(t, phase)?;
        }
        Ok(match self.transverse {
            Some(w) => c.with_transverse(w),
            None => c,
        })
    }
}

/// The oscillations in the plane in pre-slip lengths `l` (m), each checked,
/// and the fastest row's conditions (`fastest` its `vbar`) built, so that no
/// row is refused once rows are computed.
pub(super) fn pre_slip(c: &Checked, l: f64, amp: f64, fastest: f64, source: &str) -> Result<Drives> {
    let bad = |e: Error| {
        let name = match &e {
            Error::InvalidParameter { name: "transverse-amp", .. } => "oscillation.transverse_amplitude_m",
            Error::InvalidParameter { name: "transverse-phase", .. } => "oscillation.transverse_phase_rad",
            Error::InvalidParameter { name: "tangential-amp", .. } => "oscillation.tangential_amplitude_m",
            Error::InvalidParameter { name: "vhat", .. } => "velocity",
            _ => "oscillation",
        };
        Error::Parse {
            context: format!("{source}: {name}"),
            reason: format!("in pre-slip lengths l = mu0 u_z0 E*/G* = {l:?} m: {e}"),
        }
    };
    if c.tangential.is_none() && c.transverse.is_none() {
        return Ok(Drives::default());
    }
    let tangential = c.tangential.map(|(dx, phase)| (dx / l, phase));
    let transverse =
        c.transverse.map(|(dy, psi)| crate::plane::Transverse::new(dy / l, psi)).transpose().map_err(bad)?;
    let t = Drives { tangential, transverse }.conditions(fastest, amp).map_err(bad)?;
    Ok(Drives { tangential: t.tangential(), transverse })
}
