//! Independent peers of the exact solver: the seed's time-stepping scheme and
//! the seed's own approximations.
pub mod seed;
pub mod stepper;
mod stepper2d;
