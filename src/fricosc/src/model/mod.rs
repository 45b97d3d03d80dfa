//! The model: checked results ([`ratio::Ratio`]), one spring ([`spring`]) and
//! the stop operator ([`stop`]).
pub mod ratio;
pub mod spring;
pub mod stop;
