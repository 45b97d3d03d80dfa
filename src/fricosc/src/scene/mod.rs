//! Physical scenes: one experiment in SI units (a JSON file, parsed by the
//! caller with serde: feature `serde`; its schema with feature `schema`),
//! answered in SI units.
//!
//! Materials give `E*` and `G*` by the seed's eqs. 23-24; the indenter gives the
//! contact stiffness and the dimensionless shape; `vbar = (G*/E*) v0 / (mu0 omega du)`
//! (eq. 3 with `kx/kz = G*/E*` for every shape) and `amp = du/u0`.
//!
//! - Flat punch of radius `a`: `kz = 2 E* a`, `kx = 2 G* a`, one spring.
//! - Axisymmetric `f(r) = c r^n` (sphere: `n = 2, c = 1/(2R)`, the Hertz
//!   approximation; cone: `n = 1, c = ` the surface slope `cot(half angle)`): MDR
//!   equivalent profile `g = kappa(n) c |x|^n`, `kappa(n) = sqrt(pi) Gamma(n/2 + 1) /
//!   Gamma(n/2 + 1/2)`; contact radius at the mean indentation `x_c = (u0/(kappa c))^(1/n)`;
//!   `kz = 2 E* x_c`, `kx = 2 G* x_c`; mean normal force `E* x_c u0` times
//!   the contact's mean normal force ([`crate::contact::Contact::mean_normal`]).
//! - A tabulated profile (`profile`): the table's MDR transform ([`crate::contact::Table`]),
//!   redone for every mean indentation the load control tries.
//! - Load control: `u0` is solved so that the *period-averaged* normal force
//!   equals the given force. With contact loss (jumping) that differs from the
//!   static force-indentation relation; the output says so.

mod inplane;
mod solve;

pub use solve::solve_with;

use crate::error::{Error, Result};
use crate::shape::{Shape, MAX_EXPONENT, MIN_EXPONENT};
use std::f64::consts::PI;

/// One experiment.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Scene {
    /// Optional label, copied to the output.
    #[cfg_attr(feature = "serde", serde(default))]
    pub name: Option<String>,
    /// Elastic constants of the two bodies.
    pub materials: Materials,
    /// Local (Coulomb) coefficient of friction `mu0`.
    pub mu0: f64,
    /// The indenter's shape (exactly one variant).
    pub indenter: Indenter,
    /// Mean indentation or mean normal force (exactly one).
    pub loading: Loading,
    /// Normal oscillation.
    pub oscillation: Oscillation,
    /// Sliding velocities (exactly one of `values_m_per_s`, `sweep`).
    pub velocity: VelocitySpec,
    /// The tribometer's pin: its mass on a tangential system spring (absent: a
    /// stiff system, the seed's problem). Every row is then the attractor of
    /// [`crate::Conditions::with_system`].
    #[cfg_attr(feature = "serde", serde(default))]
    pub system: Option<SystemSpec>,
}

/// The body's mass, the system's tangential stiffness and its damping: in
/// the contact's units `kappa = K/kx`, `Omega = omega / sqrt(kx/m)`, `zeta =
/// c/(2 sqrt(K m))`, with `kx` the contact's tangential stiffness at the mean
/// indentation.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct SystemSpec {
    /// The body's mass (kg), > 0.
    pub mass_kg: f64,
    /// The system's tangential stiffness `K` (N/m), > 0.
    pub stiffness_n_per_m: f64,
    /// The dashpot beside it `c` (N s/m), >= 0 (default 0).
    #[cfg_attr(feature = "serde", serde(default))]
    pub damping_n_s_per_m: f64,
}

/// Young's moduli, Poisson ratios and optional shear moduli (else `E/(2(1 + nu))`).
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Materials {
    /// Young's modulus of body 1 (Pa).
    pub e1_pa: f64,
    /// Poisson ratio of body 1, in (-1, 0.5].
    pub nu1: f64,
    /// Young's modulus of body 2 (Pa).
    pub e2_pa: f64,
    /// Poisson ratio of body 2, in (-1, 0.5].
    pub nu2: f64,
    /// Shear modulus of body 1 (Pa) (default `E1/(2(1 + nu1))`).
    #[cfg_attr(feature = "serde", serde(default))]
    pub g1_pa: Option<f64>,
    /// Shear modulus of body 2 (Pa) (default `E2/(2(1 + nu2))`).
    #[cfg_attr(feature = "serde", serde(default))]
    pub g2_pa: Option<f64>,
}

/// The indenter.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case", deny_unknown_fields))]
pub enum Indenter {
    /// Flat cylindrical punch.
    FlatPunch {
        /// Punch radius (m).
        radius_m: f64,
    },
    /// Sphere (paraboloid `r^2/(2R)`, Hertz).
    Sphere {
        /// Sphere radius (m).
        radius_m: f64,
    },
    /// Cone: give the half-angle (axis to surface) or the surface slope.
    Cone {
        /// Half-angle between the axis and the surface, degrees, in (0, 90).
        #[cfg_attr(feature = "serde", serde(default))]
        half_angle_deg: Option<f64>,
        /// Surface slope `tan(90 deg - half angle)` (dimensionless).
        #[cfg_attr(feature = "serde", serde(default))]
        slope: Option<f64>,
    },
    /// Power law `f(r) = c r^n`.
    PowerLaw {
        /// Coefficient `c` [m^(1 - n)].
        c: f64,
        /// Exponent `n`, within [0.05, 1e6].
        n: f64,
    },
    /// A tabulated axisymmetric profile `f(r)` (CSV `r,f` in metres), path
    /// relative to the scene file (see `fricosc::profile`).
    Profile {
        /// The table.
        file: String,
    },
}

/// Displacement or load control (exactly one field).
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Loading {
    /// Mean indentation `u_z0` (m).
    #[cfg_attr(feature = "serde", serde(default))]
    pub mean_indentation_m: Option<f64>,
    /// Period-averaged normal force (N) (load control).
    #[cfg_attr(feature = "serde", serde(default))]
    pub mean_normal_force_n: Option<f64>,
}

/// The imposed normal oscillation `u_z0 - du cos(2 pi f t)`.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Oscillation {
    /// Amplitude `du` (m) (or give `amplitude_fraction`): one value, a list or a
    /// sweep; several amplitudes make a family of curves, one answer each.
    #[cfg_attr(feature = "serde", serde(default))]
    pub amplitude_m: Option<Values>,
    /// Amplitude as a fraction of the mean indentation, `du/u_z0`: one value, a list or a sweep.
    #[cfg_attr(feature = "serde", serde(default))]
    pub amplitude_fraction: Option<Values>,
    /// Frequency `f` (Hz) (`omega = 2 pi f`).
    pub frequency_hz: f64,
    /// Oscillation in the sliding direction, `dx sin(2 pi f t + phase)`: `dx`
    /// (m), finite and `>= 0` (0 or absent: none); `T = dx/l` in pre-slip
    /// lengths `l = mu0 u_z0 E*/G*` at most 1e6.
    #[cfg_attr(feature = "serde", serde(default))]
    pub tangential_amplitude_m: Option<f64>,
    /// Its phase (radians, finite) against the normal oscillation (default 0).
    #[cfg_attr(feature = "serde", serde(default))]
    pub tangential_phase_rad: f64,
    /// Oscillation in the plane across the sliding direction, `dy sin(2 pi f
    /// t + psi)`: `dy` (m), finite and `>= 0` (0 or absent: none); `W = dy/l` at
    /// most 1e6. Not with a `system` (not solved in the plane yet).
    #[cfg_attr(feature = "serde", serde(default))]
    pub transverse_amplitude_m: Option<f64>,
    /// Its phase `psi` (radians, `|psi| <= 1e6`) against the normal oscillation (default 0).
    #[cfg_attr(feature = "serde", serde(default))]
    pub transverse_phase_rad: f64,
}

/// One value, a list of values, or a sweep (of amplitudes).
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(
    feature = "serde",
    serde(untagged, expecting = "a number, a list of numbers, or a sweep {\"start\", \"stop\", \"count\", \"log\"}")
)]
pub enum Values {
    /// One value.
    One(f64),
    /// Values in the order given, 1 to 1000 of them.
    List(Vec<f64>),
    /// `count` values from `start` to `stop`.
    Sweep(ValueSweep),
}

/// `count` values from `start` to `stop` (inclusive), linear or logarithmic, in
/// the unit of the field that holds the sweep.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct ValueSweep {
    /// First value.
    pub start: f64,
    /// Last value.
    pub stop: f64,
    /// Number of values, 1 to 1000.
    pub count: usize,
    /// Logarithmic spacing.
    #[cfg_attr(feature = "serde", serde(default))]
    pub log: bool,
}

/// At most this many amplitudes in one scene.
pub(crate) const MAX_AMPLITUDES: usize = 1000;
/// At most this many velocities in one scene.
pub(crate) const MAX_VELOCITIES: usize = 1_000_000;
/// At most this many rows (amplitudes x velocities) in one scene.
pub(crate) const MAX_SCENE_ROWS: usize = 1_000_000;

/// Sliding velocities.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct VelocitySpec {
    /// Explicit velocities (m/s).
    #[cfg_attr(feature = "serde", serde(default))]
    pub values_m_per_s: Option<Vec<f64>>,
    /// A sweep.
    #[cfg_attr(feature = "serde", serde(default))]
    pub sweep: Option<Sweep>,
}

/// `count` velocities from `start` to `stop` (inclusive), linear or logarithmic.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Deserialize))]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
#[cfg_attr(feature = "serde", serde(deny_unknown_fields))]
pub struct Sweep {
    /// First velocity (m/s).
    pub start_m_per_s: f64,
    /// Last velocity (m/s).
    pub stop_m_per_s: f64,
    /// Number of velocities, 1 to 10^6.
    pub count: usize,
    /// Logarithmic spacing (needs `start > 0`).
    #[cfg_attr(feature = "serde", serde(default))]
    pub log: bool,
}

/// One velocity's answer (made on demand from [`Rows`]).
#[derive(Debug, Clone, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct Row {
    /// Sliding velocity (m/s).
    pub velocity_m_per_s: f64,
    /// `vbar` (eq. 3).
    pub vbar: f64,
    /// `vhat` (eq. 15).
    pub vhat: f64,
    /// Macroscopic coefficient of friction.
    pub mu_macro: f64,
    /// `mu_macro / mu0`.
    pub mu_ratio: f64,
    /// Mean friction force (N).
    pub mean_friction_force_n: f64,
    /// Mean normal force (N).
    pub mean_normal_force_n: f64,
    /// Under an oscillation across the sliding direction: `<f_y>/<B>`, the
    /// mean force across it over the mean bound (`mu0` times the mean normal force).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub transverse_ratio: Option<f64>,
    /// Under an oscillation across the sliding direction: the mean force across it (N).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub mean_transverse_force_n: Option<f64>,
    /// What the springs do ([`crate::Shape::regime`]: `sliding` at or above the
    /// critical velocity; below it `permanent_contact`, `jumping_slip_first` or
    /// `jumping_stick_first` for the flat punch, `mixed` or `jumping` for a
    /// curved contact). On a system `sliding` from its own critical velocity,
    /// below it what the contact does: `permanent_contact`, `mixed` or `jumping`.
    /// Under an oscillation in the plane (either direction) only what the
    /// contact does normally: `permanent_contact` (flat punch, `amp <= 1`),
    /// `mixed` (curved, `amp < 1`) or `jumping`.
    pub regime: crate::report::ContactRegime,
}

/// The rows of an answer, kept compact (16 bytes a row: the velocity and
/// `mu/mu0`); every other column is derived when a [`Row`] is made, so that a
/// scene of 10^6 rows holds 16 MB, and serialised as the list of rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Rows {
    velocity: Vec<f64>,
    mu_ratio: Vec<f64>,
    /// Under an oscillation across the sliding direction: `<f_y>/<B>` per velocity.
    transverse_ratio: Option<Vec<f64>>,
    /// Under an oscillation in the plane (either direction): the regime says
    /// only what the contact does normally.
    in_plane: bool,
    /// The critical velocity (m/s), `du/u0`, `mu0`, and the mean normal force (N).
    v_crit: f64,
    amp: f64,
    mu0: f64,
    normal: f64,
    /// The flat punch (its regime depends on the velocity).
    flat: bool,
    /// On a system: the `vbar` from which it slides (infinite where never).
    pub(crate) system_vbar: Option<f64>,
}

impl Rows {
    /// Row `i`.
    pub fn get(&self, i: usize) -> Option<Row> {
        let (v0, mu) = (*self.velocity.get(i)?, self.mu_ratio[i]);
        let vbar = v0 / self.v_crit;
        let across = self.transverse_ratio.as_ref().map(|t| t[i]);
        Some(Row {
            velocity_m_per_s: v0,
            vbar,
            vhat: vbar * self.amp,
            mu_macro: mu * self.mu0,
            mu_ratio: mu,
            mean_friction_force_n: mu * self.mu0 * self.normal,
            mean_normal_force_n: self.normal,
            transverse_ratio: across,
            mean_transverse_force_n: across.map(|t| t * self.mu0 * self.normal),
            regime: match self.system_vbar {
                _ if self.in_plane => match (self.flat, self.amp) {
                    (true, a) if a <= 1.0 => crate::report::ContactRegime::PermanentContact,
                    (false, a) if a < 1.0 => crate::report::ContactRegime::Mixed,
                    _ => crate::report::ContactRegime::Jumping,
                },
                None => crate::contact::regime::regime_of(self.flat, vbar, self.amp),
                Some(c) if vbar >= c || self.amp == 0.0 => crate::report::ContactRegime::Sliding,
                Some(_) if self.amp >= 1.0 => crate::report::ContactRegime::Jumping,
                Some(_) if self.flat => crate::report::ContactRegime::PermanentContact,
                Some(_) => crate::report::ContactRegime::Mixed,
            },
        })
    }

    /// Every row, in the order of the velocities.
    pub fn iter(&self) -> impl Iterator<Item = Row> + '_ {
        (0..self.velocity.len()).filter_map(|i| self.get(i))
    }

    /// The number of rows.
    pub fn len(&self) -> usize {
        self.velocity.len()
    }

    /// True without rows.
    pub fn is_empty(&self) -> bool {
        self.velocity.is_empty()
    }
}

#[cfg(feature = "serde")]
impl serde::Serialize for Rows {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        s.collect_seq(self.iter())
    }
}

/// A scene's answer.
#[derive(Debug, Clone)]
#[cfg_attr(feature = "serde", derive(serde::Serialize))]
pub struct SceneResult {
    /// The scene's name, if any.
    pub name: Option<String>,
    /// The local coefficient of friction `mu0` (as given).
    pub mu0: f64,
    /// Effective modulus `E*` (Pa) (eq. 23).
    pub e_star_pa: f64,
    /// Effective shear modulus `G*` (Pa) (eq. 24).
    pub g_star_pa: f64,
    /// Mean indentation (m) (given, or solved under load control).
    pub mean_indentation_m: f64,
    /// Oscillation amplitude (m).
    pub amplitude_m: f64,
    /// `du/u0`.
    pub amplitude_ratio: f64,
    /// Contact radius at the mean indentation (m).
    pub contact_radius_m: f64,
    /// Normal contact stiffness at the mean indentation [N/m].
    pub kz_n_per_m: f64,
    /// Tangential contact stiffness [N/m].
    pub kx_n_per_m: f64,
    /// Critical velocity (eq. 26) (m/s): the unit of `vbar`; on a stiff
    /// system, without an oscillation in the plane, no reduction at or above it.
    pub critical_velocity_m_per_s: f64,
    /// On a system: the velocity (m/s) from which its reduction vanishes
    /// ([`crate::system::critical_vbar`] critical velocities); absent where
    /// steady slip has no periodic response (then a warning says so), and
    /// under an oscillation in the sliding direction.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub system_critical_velocity_m_per_s: Option<f64>,
    /// Static coefficient of friction (the limit `v -> 0+`); absent under an
    /// oscillation in the plane (which makes the contact slip at rest).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub mu_static: Option<f64>,
    /// Period-averaged normal force (N).
    pub mean_normal_force_n: f64,
    /// Whether the contact centre loses contact during each period.
    pub jumping: bool,
    /// Under an oscillation in the plane: the pre-slip length `l = mu0 u_z0
    /// E*/G*` (m), the unit of `vhat`, `T` and `W`.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub pre_slip_length_m: Option<f64>,
    /// The oscillations in the plane in pre-slip lengths, if any.
    #[cfg_attr(feature = "serde", serde(flatten))]
    pub in_plane: crate::InPlane,
    /// Notes on the loading.
    pub note: String,
    /// On a system: its parameters in the contact's units.
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Option::is_none"))]
    pub system: Option<crate::system::System>,
    /// Where the scene leaves the model's range of validity (also printed on stderr).
    #[cfg_attr(feature = "serde", serde(skip_serializing_if = "Vec::is_empty"))]
    pub warnings: Vec<String>,
    /// One row per velocity.
    pub rows: Rows,
}

/// Largest accepted local coefficient of friction.
pub(crate) const MAX_MU0: f64 = 10.0;

/// `kappa(n) = sqrt(pi) Gamma(n/2 + 1) / Gamma(n/2 + 1/2)`: the MDR factor of `r^n`.
///
/// With `x = n/2`: for `x < 85` the two Gamma functions of `libm` (no overflow:
/// `Gamma(86) ~ 1e128`); beyond, the asymptotic series
/// `Gamma(x + 1)/Gamma(x + 1/2) = sqrt(x) (1 + 1/(8x) + 1/(128x^2) - 5/(1024x^3)`
/// `- 21/(32768x^4) + 399/(262144x^5) + 869/(4194304x^6) + ...)`, whose
/// truncation is below 4e-17 relative from `x = 85` on (checked with mpmath),
/// so that exponents up to 1e6 stay finite and exact.
#[must_use]
pub(crate) fn kappa(n: f64) -> f64 {
    let x = 0.5 * n;
    if x < 85.0 {
        PI.sqrt() * libm::tgamma(x + 1.0) / libm::tgamma(x + 0.5)
    } else {
        let y = 1.0 / x;
        let series = 1.0
            + y * (1.0 / 8.0
                + y * (1.0 / 128.0
                    + y * (-5.0 / 1024.0 + y * (-21.0 / 32768.0 + y * (399.0 / 262144.0 + y * 869.0 / 4194304.0)))));
        (PI * x).sqrt() * series
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[allow(clippy::excessive_precision)]
    /// `kappa(n)` against 20-digit mpmath values, across the switch to the series
    /// and up to the largest exponent (the hand-written Gamma overflowed from n = 283).
    #[test]
    fn kappa_matches_high_precision_values_for_every_accepted_exponent() {
        for (n, exact) in [
            (1.0, std::f64::consts::FRAC_PI_2),
            (2.0, 2.0),
            (2.5, 2.1850479619100998421),
            (3.7, 2.577353439754582866),
            (100.0, 12.564512901854901007),
            (283.0, 21.102640859202411868),
            (1000.0, 39.643182531295326472),
            (1e6, 1253.3144506440737461),
        ] {
            let rel = (kappa(n) / exact - 1.0).abs();
            assert!(rel < 4e-15, "n = {n}: {} vs {exact} ({rel:e})", kappa(n));
        }
        // Continuous across the switch at n = 170.
        let (a, b) = (kappa(169.99999999999997), kappa(170.0));
        assert!((a / b - 1.0).abs() < 1e-15);
    }
}
