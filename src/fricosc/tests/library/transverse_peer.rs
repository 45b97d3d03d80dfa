//! The stop operator in the plane by time stepping (`fricosc::stepper::transverse`),
//! the peer of oscillation across the sliding direction: along one line it
//! is the one-dimensional peer bit for bit; its rigid limit is Gauss's
//! constant (an arithmetic-geometric mean, independent of any stepping),
//! approached like the pre-slip length over the amplitude; a transverse
//! force appears only where a symmetry does not forbid it.
use fricosc::plane::Transverse;
use fricosc::stepper::{rigid_limit, transverse, Stepping};
use fricosc::{Conditions, Shape};

fn run(shape: &Shape, c: &Conditions, w: (f64, f64), steps: usize, springs: usize) -> (f64, f64, f64) {
    let st = Stepping { steps_per_period: steps, springs };
    let r = transverse(shape, c, Transverse::new(w.0, w.1).unwrap(), st, 16).unwrap();
    (r.mu_ratio, r.transverse_ratio, r.period_change)
}

/// Without transverse motion the plane's peer is the sliding direction's
/// (`--method stepping` under a tangential oscillation), bit for bit, for
/// the flat punch and a paraboloid's springs; the force across is 0 exactly.
#[test]
fn along_one_line_it_is_the_one_dimensional_peer() {
    for (shape, springs) in [(Shape::flat(), 1), (Shape::parabolic(), 64)] {
        let c = Conditions::vhat(0.3, 1.4).unwrap().with_tangential(0.8, 0.6).unwrap();
        let st = Stepping { steps_per_period: 512, springs };
        let one = fricosc::stepper::evaluate(&shape, &c, st).unwrap().ratio.mu_ratio;
        let (mu, across, _) = run(&shape, &c, (0.0, 0.3), 512, springs);
        let three = transverse(&shape, &c, Transverse::new(0.0, 0.3).unwrap(), st, 3).unwrap();
        assert_eq!((three.mu_ratio, across), (one, 0.0), "{}", shape.name());
        assert!((mu - one).abs() < 1e-12, "{mu} {one}");
    }
}

/// The rigid limit at `W = vhat` is Gauss's constant `1/AGM(1, sqrt 2) =
/// 0.8346268416740731862814297...`; the stepped flat punch (amp 0, T 0)
/// approaches it like `1/A^2` at amplitudes `vhat = W = A`: the force lags
/// the velocity's direction `theta` by an angle `delta` of order `1/A` (a
/// pre-slip length over the amplitude), and `cos(theta - delta)` moves `<f_x>`
/// at first order by `<delta sin theta>`, with `delta` following `theta'`:
/// the mean of a derivative, 0. Observed 1.14e-3, 1.16e-5, 1.16e-7 at `A`
/// 10, 100, 1000 at 100 `A` steps a period (the stepping's own error is
/// smaller: 4 times the steps move `A = 100`'s by 6e-7).
#[test]
fn the_rigid_limit_is_gauss_constant() {
    assert!((rigid_limit(1.0) - 0.834_626_841_674_073_2).abs() < 2e-16);
    assert_eq!(rigid_limit(0.0), 1.0);
    let err = |a: f64| {
        let c = Conditions::vhat(a, 0.0).unwrap();
        (run(&Shape::flat(), &c, (a, 0.4), 100 * a as usize, 1).0 - rigid_limit(1.0)).abs()
    };
    let (e10, e100) = (err(10.0), err(100.0));
    assert!(e100 < 2e-5 && (80.0..120.0).contains(&(e10 / e100)), "{e10:e} {e100:e}");
}

/// Without normal or tangential oscillation a shift of half a period mirrors
/// `y` (the transverse motion's phase moves by `pi`, the bound and the
/// sliding stay): no mean force across, whatever `W` and `psi` (1.7e-16 of
/// `<B>` once periodic, after 16 periods). A normal oscillation changes the
/// bound under that shift: a mean force across appears (a ratchet), here
/// -0.247 of `<B>` against `mu` 0.615.
#[test]
fn a_force_across_needs_a_broken_symmetry() {
    let (_, across, change) = run(&Shape::flat(), &Conditions::vhat(0.3, 0.0).unwrap(), (1.2, 0.7), 4096, 1);
    assert!(across.abs() < 1e-14 && change == 0.0, "{across:e} {change:e}");
    let (mu, across, change) = run(&Shape::flat(), &Conditions::vhat(0.3, 0.5).unwrap(), (1.2, 0.7), 4096, 1);
    assert!(across < -0.2 && mu > 0.6 && change == 0.0, "{mu} {across:e} {change:e}");
}

/// Without sliding or tangential oscillation (`vhat = 0`, `T = 0`) mirroring
/// `x` maps the motion onto itself: no mean force along `x`. From the start
/// along `x` it decays by a factor each period (1e-39 of `<B>` after 64
/// periods at du/u0 0.5); a spring that loses contact starts each period
/// relaxed: 0 exactly (du/u0 1.5). The force across stays (-0.347 and -0.744).
#[test]
fn without_sliding_no_mean_force_along_the_sliding_direction() {
    let st = Stepping { steps_per_period: 4096, springs: 1 };
    let w = Transverse::new(1.2, 0.7).unwrap();
    let r = transverse(&Shape::flat(), &Conditions::vhat(0.0, 0.5).unwrap(), w, st, 64).unwrap();
    assert!(r.mu_ratio.abs() < 1e-20 && r.transverse_ratio < -0.3, "{r:?}");
    let r = transverse(&Shape::flat(), &Conditions::vhat(0.0, 1.5).unwrap(), w, st, 2).unwrap();
    assert!(r.mu_ratio == 0.0 && r.period_change == 0.0 && r.transverse_ratio < -0.7, "{r:?}");
}

/// Does static friction survive transverse shaking (amp 0, T 0, `vhat -> 0`)?
/// While sticking the force follows the body, so its `y` swings by `+-W`
/// about a centre; slips at the swing's ends centre it at 0, and creeping
/// along `x` the force settles where the whole swing just fits the disc of
/// radius 1: `f_x = sqrt(1 - W^2)`. So for `W < 1` friction tends to
/// `sqrt(1 - W^2)` (0.8 at `W = 0.6`: 0.8208 and 0.8023 at `vhat` 1e-2 and
/// 1e-3, the excess falling like `vhat`); for `W >= 1` the swing never fits,
/// the force slides round the circle, and friction vanishes like `vhat`
/// (`mu/vhat` 3.2627 at `W = 1.5`, the same to 1.1e-5 at 1e-3 and 1e-4).
#[test]
fn static_friction_survives_a_transverse_swing_below_the_preslip_length() {
    let st = Stepping { steps_per_period: 8192, springs: 1 };
    let mu = |vhat: f64, w: f64| {
        let c = Conditions::vhat(vhat, 0.0).unwrap();
        transverse(&Shape::flat(), &c, Transverse::new(w, 0.3).unwrap(), st, 64).unwrap().mu_ratio
    };
    let (a, b) = (mu(1e-2, 0.6) - 0.8, mu(1e-3, 0.6) - 0.8);
    assert!(b > 0.0 && b < 5e-3 && (7.0..12.0).contains(&(a / b)), "{a:e} {b:e}");
    let (a, b) = (mu(1e-3, 1.5) / 1e-3, mu(1e-4, 1.5) / 1e-4);
    assert!(a > 3.0 && (a / b - 1.0).abs() < 1e-4, "{a} {b}");
}
