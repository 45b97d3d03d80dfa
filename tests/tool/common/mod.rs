//! Support shared by the tool's tests.
pub mod rows;
pub mod run;

/// The library's facade at the numbers the tests use.
pub mod at {
    use fricosc::report::Combined;
    use fricosc::stepper::{Stepping, SteppingEvaluation};
    use fricosc::{Conditions, Report, Result, Shape};

    /// The stepping peer at `(vbar, amp)`.
    pub fn stepped(shape: &Shape, vbar: f64, amp: f64, st: Stepping) -> Result<SteppingEvaluation> {
        fricosc::stepper::evaluate(shape, &Conditions::vbar(vbar, amp)?, st)
    }

    /// The solver under a tangential oscillation: the answer with the spring or bands.
    pub fn combined(shape: &Shape, vhat: f64, amp: f64, t: f64, phase: f64) -> Result<Combined> {
        match shape.report(&Conditions::vhat(vhat, amp)?.with_tangential(t, phase)?)? {
            Report::Tangential(r) => Ok(r.result),
            r => panic!("a tangential report expected, got {r:?}"),
        }
    }
}

/// `shape` at `(vbar, amp)`.
pub fn eval(shape: &fricosc::Shape, vbar: f64, amp: f64) -> fricosc::Result<fricosc::Evaluation> {
    shape.evaluate(&fricosc::Conditions::vbar(vbar, amp)?)
}

/// The attractor of `shape` at `c` with the body on `sys`, through the
/// library's one way in.
pub fn on_system(
    shape: &fricosc::Shape,
    c: &fricosc::Conditions,
    sys: &fricosc::system::System,
) -> fricosc::Result<fricosc::system::SystemReport> {
    match shape.report(&c.with_system(*sys))? {
        fricosc::Report::System(r) => Ok(r),
        other => panic!("a report on a system is the system's: {other:?}"),
    }
}
