//! Solving a scene: its fields checked, the indenter's geometry, load control,
//! and the rows of every amplitude.

use super::inplane::{in_plane, pre_slip, Drives};
use super::*;
use crate::root;

pub(super) struct Checked {
    e_star: f64,
    g_star: f64,
    mu0: f64,
    omega: f64,
    geometry: Geometry,
    velocities: Vec<f64>,
    /// The oscillations in the plane: `(dx, phase)` and `(dy, psi)` (m, radians), where given and > 0.
    pub(super) tangential: Option<(f64, f64)>,
    pub(super) transverse: Option<(f64, f64)>,
}

/// The indenter of a scene, checked, in SI units.
enum Geometry {
    /// A flat punch of this radius (m).
    Flat { radius: f64 },
    /// The MDR profile `g = kc |x|^n` (`kc = kappa(n) c` for `f = c r^n`).
    Power { n: f64, kc: f64 },
    /// A tabulated profile's path and its table, read and transformed once
    /// (its normalised shape depends on the mean indentation).
    Profile { path: String, table: crate::profile::Table },
}

impl Geometry {
    /// The shape at mean indentation `u0` (m) and its contact radius (m).
    fn at(&self, u0: f64) -> Result<(Shape, f64)> {
        Ok(match self {
            Geometry::Flat { radius } => (Shape::flat(), *radius),
            Geometry::Power { n, kc } => (Shape::power(*n)?, (u0 / kc).powf(1.0 / n)),
            Geometry::Profile { path, table } => {
                let t = table.at(u0)?.named(&format!("profile:{path}@{u0:?}"));
                let xc = t.contact_radius;
                (Shape::from_contact(std::sync::Arc::new(t)), xc)
            }
        })
    }
}

pub(super) fn field(source: &str, path: &str, value: f64, ok: bool, what: &str) -> Result<f64> {
    if value.is_finite() && ok {
        Ok(value)
    } else {
        Err(Error::Parse { context: format!("{source}: {path}"), reason: format!("{value:?} {what}") })
    }
}

fn check(s: &Scene, source: &str, read: crate::contact::Reader) -> Result<Checked> {
    let m = &s.materials;
    let pos = |p: &str, v: f64| field(source, p, v, v > 0.0, "must be finite and > 0");
    let nu = |p: &str, v: f64| field(source, p, v, v > -1.0 && v <= 0.5, "must be in (-1, 0.5]");
    let (e1, e2) = (pos("materials.e1_pa", m.e1_pa)?, pos("materials.e2_pa", m.e2_pa)?);
    let (n1, n2) = (nu("materials.nu1", m.nu1)?, nu("materials.nu2", m.nu2)?);
    let g1 = match m.g1_pa {
        Some(g) => pos("materials.g1_pa", g)?,
        None => e1 / (2.0 * (1.0 + n1)),
    };
    let g2 = match m.g2_pa {
        Some(g) => pos("materials.g2_pa", g)?,
        None => e2 / (2.0 * (1.0 + n2)),
    };
    let e_star = 1.0 / ((1.0 - n1 * n1) / e1 + (1.0 - n2 * n2) / e2);
    let g_star = 1.0 / ((2.0 - n1) / (4.0 * g1) + (2.0 - n2) / (4.0 * g2));
    // The effective moduli (eqs. 23-24) must be ordinary positive numbers: a
    // subnormal or huge modulus overflows them to 0 or infinity.
    for (name, v) in
        [("E* (eq. 23, from materials.e1_pa, e2_pa, nu1, nu2)", e_star), ("G* (eq. 24, from materials)", g_star)]
    {
        if !(v.is_normal() && v > 0.0 && (1.0 / v).is_normal()) {
            return Err(Error::Parse {
                context: format!("{source}: materials"),
                reason: format!("{name} = {v:?} is outside double precision's normal range"),
            });
        }
    }
    let mu0 =
        field(source, "mu0", s.mu0, s.mu0 > 0.0 && s.mu0 <= MAX_MU0, "must be in (0, 10] (a Coulomb coefficient)")?;
    let f_hz = pos("oscillation.frequency_hz", s.oscillation.frequency_hz)?;
    let omega = field(source, "oscillation.frequency_hz", f_hz, (2.0 * PI * f_hz).is_finite(), "overflows 2 pi f")?
        * (2.0 * PI);
    let geometry = geometry(s, source, read)?;
    let velocities = match (&s.velocity.values_m_per_s, &s.velocity.sweep) {
        (Some(v), None) => {
            if v.is_empty() || v.len() > MAX_VELOCITIES {
                return Err(Error::Parse {
                    context: format!("{source}: velocity.values_m_per_s"),
                    reason: "needs 1 to 10^6 values".into(),
                });
            }
            v.iter()
                .enumerate()
                .map(|(i, &x)| {
                    field(source, &format!("velocity.values_m_per_s[{i}]"), x, x >= 0.0, "must be finite and >= 0")
                })
                .collect::<Result<Vec<_>>>()?
        }
        (None, Some(sw)) => sweep(
            source,
            ("velocity.sweep.start_m_per_s", "velocity.sweep.stop_m_per_s", "velocity.sweep.count"),
            (sw.start_m_per_s, sw.stop_m_per_s, sw.count, sw.log),
            MAX_VELOCITIES,
            true,
        )?,
        _ => {
            return Err(Error::Parse {
                context: format!("{source}: velocity"),
                reason: "give exactly one of values_m_per_s, sweep".into(),
            })
        }
    };
    let (tangential, transverse) = in_plane(s, source)?;
    Ok(Checked { e_star, g_star, mu0, omega, geometry, velocities, tangential, transverse })
}

/// The indenter's geometry in the solver's terms, checked.
fn geometry(s: &Scene, source: &str, read: crate::contact::Reader) -> Result<Geometry> {
    let pos = |p: &str, v: f64| field(source, p, v, v > 0.0, "must be finite and > 0");
    Ok(match &s.indenter {
        Indenter::FlatPunch { radius_m } => Geometry::Flat { radius: pos("indenter.flat_punch.radius_m", *radius_m)? },
        Indenter::Sphere { radius_m } => {
            Geometry::Power { n: 2.0, kc: 1.0 / pos("indenter.sphere.radius_m", *radius_m)? }
        }
        Indenter::Cone { half_angle_deg, slope } => {
            let slope = match (half_angle_deg, slope) {
                (Some(h), None) => {
                    let h =
                        field(source, "indenter.cone.half_angle_deg", *h, *h > 0.0 && *h < 90.0, "must be in (0, 90)")?;
                    1.0 / h.to_radians().tan()
                }
                (None, Some(sl)) => pos("indenter.cone.slope", *sl)?,
                _ => {
                    return Err(Error::Parse {
                        context: format!("{source}: indenter.cone"),
                        reason: "give exactly one of half_angle_deg, slope".into(),
                    })
                }
            };
            Geometry::Power { n: 1.0, kc: PI / 2.0 * slope }
        }
        Indenter::PowerLaw { c, n } => {
            let n = field(
                source,
                "indenter.power_law.n",
                *n,
                (MIN_EXPONENT..=MAX_EXPONENT).contains(n),
                "must be in [0.05, 1e6]",
            )?;
            Geometry::Power { n, kc: kappa(n) * pos("indenter.power_law.c", *c)? }
        }
        Indenter::Profile { file } => {
            let dir = std::path::Path::new(source).parent().unwrap_or(std::path::Path::new(""));
            let path = dir.join(file).to_string_lossy().into_owned();
            let text = read(&path).map_err(|e| Error::File { path: path.clone(), source: Box::new(e) })?;
            let table = crate::profile::Table::parse(&text, &path, true)?;
            Geometry::Profile { path, table }
        }
    })
}

/// `count` values from `start` to `stop` (inclusive; `names` are the three
/// fields' paths for errors), linear or logarithmic, at most `max`, tidied to
/// their decimal values where the spacing only added binary noise
/// (0.005000000000000001 -> 0.005). `zero_ok`: whether `start` may be 0.
fn sweep(
    source: &str,
    names: (&str, &str, &str),
    (start, stop, count, log): (f64, f64, usize, bool),
    max: usize,
    zero_ok: bool,
) -> Result<Vec<f64>> {
    let a = if zero_ok {
        field(source, names.0, start, start >= 0.0, "must be >= 0")?
    } else {
        field(source, names.0, start, start > 0.0, "must be > 0")?
    };
    let b = field(source, names.1, stop, stop >= a, "must be >= start")?;
    if count == 0 || count > max {
        return Err(Error::Parse { context: format!("{source}: {}", names.2), reason: format!("must be 1 to {max}") });
    }
    if log && a <= 0.0 {
        return Err(Error::Parse {
            context: format!("{source}: {}", names.0),
            reason: "a log sweep needs start > 0".into(),
        });
    }
    Ok(crate::spaced(a, b, count, log))
}

/// The amplitudes of `values` at the field `path`, each finite and > 0.
fn amplitudes(source: &str, path: &str, values: &Values) -> Result<Vec<f64>> {
    let positive = |p: &str, x: f64| field(source, p, x, x > 0.0, "must be finite and > 0");
    match values {
        Values::One(x) => Ok(vec![positive(path, *x)?]),
        Values::List(v) => {
            if v.is_empty() || v.len() > MAX_AMPLITUDES {
                return Err(Error::Parse {
                    context: format!("{source}: {path}"),
                    reason: format!("needs 1 to {MAX_AMPLITUDES} values"),
                });
            }
            v.iter().enumerate().map(|(i, &x)| positive(&format!("{path}[{i}]"), x)).collect()
        }
        Values::Sweep(sw) => sweep(
            source,
            (&format!("{path}.start"), &format!("{path}.stop"), &format!("{path}.count")),
            (sw.start, sw.stop, sw.count, sw.log),
            MAX_AMPLITUDES,
            false,
        ),
    }
}

/// The amplitude of one member of a scene's family: in metres, or as a fraction of `u0`.
#[derive(Debug, Clone, Copy)]
enum Amplitude {
    Metres(f64),
    Fraction(f64),
}

impl Amplitude {
    fn at(self, u0: f64) -> f64 {
        match self {
            Amplitude::Metres(d) => d,
            Amplitude::Fraction(f) => f * u0,
        }
    }
}

/// The scene's amplitudes, each one answer.
fn family(s: &Scene, source: &str) -> Result<Vec<Amplitude>> {
    match (&s.oscillation.amplitude_m, &s.oscillation.amplitude_fraction) {
        // Without oscillation vbar is infinite and mu = mu0 at every velocity: nothing to compute.
        (Some(v), None) => {
            Ok(amplitudes(source, "oscillation.amplitude_m", v)?.into_iter().map(Amplitude::Metres).collect())
        }
        (None, Some(v)) => {
            Ok(amplitudes(source, "oscillation.amplitude_fraction", v)?.into_iter().map(Amplitude::Fraction).collect())
        }
        _ => Err(Error::Parse {
            context: format!("{source}: oscillation"),
            reason: "give exactly one of amplitude_m, amplitude_fraction".into(),
        }),
    }
}

/// Contact radius, `kz`, and the mean normal force (N) at mean indentation `u0`, amplitude `du`.
fn contact(c: &Checked, u0: f64, du: f64) -> Result<(f64, f64, f64)> {
    let amp = du / u0;
    // The contact radius from the scene's indenter; the force from the contact
    // (Contact::mean_normal, units E* x_c u0; the stiffness is 2 E* x_c).
    let (shape, xc) = c.geometry.at(u0)?;
    let kz = 2.0 * c.e_star * xc;
    let m = shape.contact().mean_normal(amp)?;
    Ok((xc, kz, kz * u0 * (m / 2.0)))
}

impl Scene {
    /// Number of rows of the scene (velocities times amplitudes, for progress reporting), if it parses.
    #[must_use]
    pub fn rows(&self) -> usize {
        let v = match (&self.velocity.values_m_per_s, &self.velocity.sweep) {
            (Some(v), _) => v.len(),
            (None, Some(sw)) => sw.count,
            _ => 0,
        };
        let count = |a: &Values| match a {
            Values::One(_) => 1,
            Values::List(l) => l.len(),
            Values::Sweep(sw) => sw.count,
        };
        let o = &self.oscillation;
        v.saturating_mul(o.amplitude_m.as_ref().or(o.amplitude_fraction.as_ref()).map_or(1, count))
    }
}

/// Solve a scene, one answer per amplitude (in the order given); `source` is
/// its path (a tabulated profile's file is found relative to it and its text
/// supplied by `read`: the core reads no files), calling `progress(k)` after
/// each chunk of `k` velocities. Every amplitude and velocity is checked, and
/// the size limits enforced, before any is computed.
///
/// # Errors
/// [`Error::Parse`] naming the field for a value out of its range,
/// [`Error::File`] when the reader fails, [`Error::TooLarge`] beyond the limits.
pub fn solve_with(
    s: &Scene,
    source: &str,
    read: crate::contact::Reader,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<Vec<SceneResult>> {
    let c = check(s, source, read)?;
    let amps = family(s, source)?;
    let rows = amps.len().saturating_mul(c.velocities.len());
    if rows > MAX_SCENE_ROWS {
        return Err(Error::TooLarge {
            what: format!("{source}: rows (amplitudes x velocities)"),
            count: rows as u128,
            limit: MAX_SCENE_ROWS as u128,
        });
    }
    amps.iter().map(|&a| solve_amplitude(s, &c, a, source, progress)).collect()
}

/// One member of a scene's family.
fn solve_amplitude(
    s: &Scene,
    c: &Checked,
    amplitude: Amplitude,
    source: &str,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<SceneResult> {
    let amp_of = |u0: f64| -> Result<f64> { Ok(amplitude.at(u0)) };
    let (u0, note) = mean_indentation(s, c, &amp_of, source)?;
    let (shape, _) = c.geometry.at(u0)?;
    let du = amp_of(u0)?;
    let amp = du / u0;
    let (xc, kz, fbar) = contact(c, u0, du)?;
    let ratio = c.g_star / c.e_star;
    let v_crit = critical_velocity(c, du, source)?;
    let warnings = sphere_warnings(s, xc, u0, source)?;
    let mu_static = if c.tangential.is_some() || c.transverse.is_some() {
        None
    } else {
        Some(shape.mu_static(amp, crate::DEFAULT_TOL)? * c.mu0)
    };
    let system = s.system.as_ref().map(|spec| system_of(spec, kz * ratio, c.omega, source)).transpose()?;
    let vbars: Vec<f64> = c.velocities.iter().map(|v0| v0 / v_crit).collect();
    let l = c.mu0 * u0 / ratio;
    let plane = pre_slip(c, l, amp, vbars.iter().copied().fold(0.0, f64::max), source)?;
    let in_plane = plane.any();
    let (mu_ratio, transverse_ratio) = mu_ratios(&shape, (&vbars, amp), system.as_ref(), plane, progress)?;
    let system_vbar = match &system {
        // The critical velocity is the normal oscillation's: none under one in the sliding direction.
        Some(_) if in_plane => None,
        Some(sys) => Some(crate::system::critical_vbar(&shape, amp, sys)?.unwrap_or(f64::INFINITY)),
        None => None,
    };
    let mut warnings = warnings;
    if system_vbar == Some(f64::INFINITY) {
        warnings.push("on this system steady slip has no periodic response (an undamped slip resonance): the reduction does not vanish at any velocity".into());
    }
    let flat = shape.is_flat();
    let rows = Rows {
        velocity: c.velocities.clone(),
        mu_ratio,
        transverse_ratio,
        in_plane,
        v_crit,
        amp,
        mu0: c.mu0,
        normal: fbar,
        flat,
        system_vbar,
    };
    // Every number of the answer must be finite: an overflow names its field.
    let scalars = [
        ("e_star_pa", c.e_star),
        ("g_star_pa", c.g_star),
        ("mean_indentation_m", u0),
        ("amplitude_m", du),
        ("amplitude_ratio", amp),
        ("contact_radius_m", xc),
        ("kz_n_per_m", kz),
        ("kx_n_per_m", kz * ratio),
        ("critical_velocity_m_per_s", v_crit),
        ("mu_static", mu_static.unwrap_or(0.0)),
        ("mean_normal_force_n", fbar),
        ("pre_slip_length_m", l),
    ];
    finite(&scalars, &rows, source)?;
    Ok(SceneResult {
        name: s.name.clone(),
        mu0: c.mu0,
        e_star_pa: c.e_star,
        g_star_pa: c.g_star,
        mean_indentation_m: u0,
        amplitude_m: du,
        amplitude_ratio: amp,
        contact_radius_m: xc,
        kz_n_per_m: kz,
        kx_n_per_m: kz * ratio,
        critical_velocity_m_per_s: v_crit,
        system_critical_velocity_m_per_s: system_vbar.map(|c| c * v_crit).filter(|v| v.is_finite()),
        mu_static,
        mean_normal_force_n: fbar,
        jumping: amp > 1.0,
        pre_slip_length_m: in_plane.then_some(l),
        in_plane: crate::InPlane::new(plane.tangential, plane.transverse),
        note,
        system,
        warnings,
        rows,
    })
}

/// Eq. 26's critical velocity `mu0 omega du E*/G*` (m/s), the unit of `vbar`
/// (eq. 3 with `kx/kz = G*/E*`: `vbar = v0/v_crit`): refused unless an
/// ordinary number, else every `vbar` is 0, infinite or NaN.
fn critical_velocity(c: &Checked, du: f64, source: &str) -> Result<f64> {
    let v_crit = c.mu0 * c.omega * du / (c.g_star / c.e_star);
    if v_crit.is_normal() && v_crit > 0.0 {
        return Ok(v_crit);
    }
    Err(Error::Parse {
        context: source.into(),
        reason: format!(
            "the critical velocity mu0 omega du E*/G* = {v_crit:?} m/s is outside double precision \
             (check mu0, oscillation.frequency_hz, the amplitude and the materials)"
        ),
    })
}

/// Every number of a scene's answer finite: an overflow names its field.
fn finite(scalars: &[(&str, f64)], rows: &Rows, source: &str) -> Result<()> {
    let overflow = |name: &str, v: f64| Error::Parse {
        context: source.into(),
        reason: format!("{name} = {v:?}: the scene's values overflow double precision"),
    };
    if let Some((name, v)) = scalars.iter().find(|(_, v)| !v.is_finite()) {
        return Err(overflow(name, *v));
    }
    for (i, r) in rows.iter().enumerate() {
        for (name, v) in [
            ("vbar", r.vbar),
            ("vhat", r.vhat),
            ("mu_macro", r.mu_macro),
            ("mean_friction_force_n", r.mean_friction_force_n),
            ("mean_transverse_force_n", r.mean_transverse_force_n.unwrap_or(0.0)),
        ] {
            if !v.is_finite() {
                return Err(overflow(&format!("rows[{i}].{name} (velocity {:?} m/s)", r.velocity_m_per_s), v));
            }
        }
    }
    Ok(())
}

/// `mu/mu0` and, under a transverse oscillation, `<f_y>/<B>` at every `vbar`
/// (on every core, in chunks that report `progress`), on the system if any,
/// with the oscillations in the plane if any.
fn mu_ratios(
    shape: &crate::Shape,
    (vbars, amp): (&[f64], f64),
    system: Option<&crate::system::System>,
    drives: Drives,
    progress: &(dyn Fn(u64) + Sync),
) -> Result<(Vec<f64>, Option<Vec<f64>>)> {
    let mut mu_ratio = Vec::with_capacity(vbars.len());
    let mut across = drives.transverse.map(|_| Vec::with_capacity(vbars.len()));
    let in_plane = drives.any();
    for chunk in vbars.chunks(1024) {
        let mus = crate::numerics::par::map(chunk, |&vbar| -> Result<(f64, Option<f64>)> {
            // At or above the critical velocity no spring is computed.
            if vbar >= 1.0 && !in_plane && system.is_none() {
                return Ok((1.0, None));
            }
            let c = drives.conditions(vbar, amp)?;
            Ok(match system {
                Some(&sys) => (shape.ratio(&c.with_system(sys))?.mu_ratio, None),
                None => {
                    let e = shape.evaluate(&c)?;
                    (e.ratio.mu_ratio, e.transverse_ratio)
                }
            })
        });
        for m in mus {
            let (mu, t) = m?;
            mu_ratio.push(mu);
            if let (Some(a), Some(t)) = (across.as_mut(), t) {
                a.push(t);
            }
        }
        progress(chunk.len() as u64);
    }
    Ok((mu_ratio, across))
}

/// The system in the contact's units (`kx` its tangential stiffness, `omega`
/// the drive's angular frequency): `kappa = K/kx`, `Omega = omega
/// sqrt(m/kx)`, `zeta = c/(2 sqrt(K m))`, each checked as
/// [`crate::system::System::new`] checks it.
fn system_of(spec: &super::SystemSpec, kx: f64, omega: f64, source: &str) -> Result<crate::system::System> {
    let (m, k, c) = (spec.mass_kg, spec.stiffness_n_per_m, spec.damping_n_s_per_m);
    for (name, v, low) in [("system.mass_kg", m, 0.0), ("system.stiffness_n_per_m", k, 0.0)] {
        if !(v.is_finite() && v > low) {
            return Err(Error::Parse {
                context: source.into(),
                reason: format!("{name} = {v:?}: must be finite and > 0"),
            });
        }
    }
    if !(c.is_finite() && c >= 0.0) {
        return Err(Error::Parse {
            context: source.into(),
            reason: format!("system.damping_n_s_per_m = {c:?}: must be finite and >= 0"),
        });
    }
    crate::system::System::new(k / kx, omega * (m / kx).sqrt(), c / (2.0 * (k * m).sqrt())).map_err(|e| {
        // The ratio refused, and the scene's values it is made of.
        let from = match &e {
            Error::InvalidParameter { name: "system-stiffness", .. } => "kappa = K/kx, from stiffness_n_per_m",
            Error::InvalidParameter { name: "frequency-ratio", .. } => {
                "Omega = omega sqrt(m/kx), from mass_kg and the frequency"
            }
            Error::InvalidParameter { name: "damping", .. } => {
                "zeta = c/(2 sqrt(K m)), from damping_n_s_per_m, stiffness_n_per_m and mass_kg"
            }
            _ => "the system",
        };
        Error::Parse { context: source.into(), reason: format!("system ({from}): {e}") }
    })
}

/// The mean indentation: given, or solved from the mean normal force (with a note saying so).
fn mean_indentation(
    s: &Scene,
    c: &Checked,
    amp_of: &dyn Fn(f64) -> Result<f64>,
    source: &str,
) -> Result<(f64, String)> {
    let l = &s.loading;
    Ok(match (l.mean_indentation_m, l.mean_normal_force_n) {
        (Some(u), None) => {
            (field(source, "loading.mean_indentation_m", u, u > 0.0, "must be finite and > 0")?, String::new())
        }
        (None, Some(f)) => {
            let f = field(source, "loading.mean_normal_force_n", f, f > 0.0, "must be finite and > 0")?;
            (
                solve_load(c, f, amp_of, source)?,
                "load control: u_z0 solved so that the period-averaged normal force equals \
              mean_normal_force_n; with contact loss this differs from the static force-indentation relation"
                    .into(),
            )
        }
        _ => {
            return Err(Error::Parse {
                context: format!("{source}: loading"),
                reason: "give exactly one of mean_indentation_m, mean_normal_force_n".into(),
            })
        }
    })
}

/// A sphere's contact radius against its radius: beyond it an error, beyond a
/// tenth of it a warning (Hertz, the paraboloid, no longer applies).
fn sphere_warnings(s: &Scene, xc: f64, u0: f64, source: &str) -> Result<Vec<String>> {
    let mut warnings = vec![];
    if let Indenter::Sphere { radius_m } = s.indenter {
        // Hertz (a paraboloid) needs a contact radius small against the sphere's.
        if xc > radius_m {
            return Err(Error::Parse {
                context: format!("{source}: loading"),
                reason: format!(
                    "contact radius {xc:?} m exceeds the sphere radius {radius_m:?} m (mean indentation {u0:?} m): \
                     impossible for a sphere"
                ),
            });
        }
        if xc > 0.1 * radius_m {
            warnings.push(format!(
                "contact radius {xc:.3e} m is more than 0.1 of the sphere radius {radius_m:.3e} m: Hertz (the \
                 paraboloid used here) no longer applies; use a tabulated 'profile' of the sphere"
            ));
        }
    }
    Ok(warnings)
}

/// `u0` with period-averaged normal force `f` (the force grows with `u0`).
fn solve_load(c: &Checked, f: f64, amp_of: &dyn Fn(f64) -> Result<f64>, source: &str) -> Result<f64> {
    // NaN where the table cannot carry the contact (it then ends the bracketing).
    let force = |u0: f64| -> f64 {
        let du = amp_of(u0).unwrap_or(f64::NAN);
        contact(c, u0, du).map_or(f64::NAN, |x| x.2)
    };
    // Static guess (no oscillation), then bracket by factors of 2 in u0.
    let guess = match &c.geometry {
        // A tabulated profile: start from a thousandth of the table's depth.
        Geometry::Profile { table, .. } => table.max_g() * 1e-3,
        Geometry::Flat { radius } => f / (2.0 * c.e_star * radius),
        Geometry::Power { n, kc } => (f * kc.powf(1.0 / n) * (n + 1.0) / (2.0 * n * c.e_star)).powf(n / (n + 1.0)),
    };
    let bad = |reason: String| Error::Parse { context: format!("{source}: loading.mean_normal_force_n"), reason };
    if !(guess.is_finite() && guess > 0.0) {
        return Err(bad(format!("{f:?} N: the static indentation estimate {guess:?} m overflows double precision")));
    }
    let (mut lo, mut hi) = (guess, guess);
    for _ in 0..200 {
        let fl = force(lo);
        if fl <= f || fl.is_nan() || !(0.5 * lo).is_normal() {
            break;
        }
        lo *= 0.5;
    }
    for _ in 0..200 {
        if force(hi) >= f || !(2.0 * hi).is_finite() {
            break;
        }
        hi *= 2.0;
    }
    let (flo, fhi) = (force(lo), force(hi));
    if flo.is_nan() {
        // The contact itself failed there (a tabulated profile that does not
        // resolve it): say why.
        let why =
            amp_of(lo).and_then(|du| contact(c, lo, du)).err().map_or("no finite force".to_string(), |e| e.to_string());
        return Err(bad(format!("{f:?} N: searching down to a mean indentation of {lo:?} m failed: {why}")));
    }
    if flo > f {
        return Err(bad(format!(
            "{f:?} N cannot be reached at this amplitude: the smallest reachable mean normal force is about \
             {flo:.6e} N (mean indentation -> 0, the indenter jumping)"
        )));
    }
    if !(fhi >= f && fhi.is_finite()) {
        return Err(bad(format!("{f:?} N is beyond what double precision can represent for this indenter")));
    }
    let u = root::bracketed(|u| force(u) - f, lo, hi, 1e-15).x;
    // Polish: of the doubles within 8 ulps of the root, the one whose force is
    // closest to `f` (often `f` itself), so that a force of 2 N is not printed
    // as 1.9999999999999998 N where a neighbouring indentation gives 2 exactly.
    // The force printed is always the one computed at the indentation used.
    let mut best = (u, (force(u) - f).abs());
    let (mut down, mut up) = (u, u);
    for _ in 0..8 {
        down = down.next_down();
        up = up.next_up();
        for x in [down, up] {
            let d = (force(x) - f).abs();
            if d < best.1 {
                best = (x, d);
            }
        }
        if best.1 == 0.0 {
            break;
        }
    }
    Ok(best.0)
}
