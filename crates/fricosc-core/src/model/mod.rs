//! The model: checked results ([`ratio::Ratio`]) and one spring ([`spring`]).
pub mod ratio;
pub mod spring;
