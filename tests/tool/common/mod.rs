//! Support shared by the tool's tests.
pub mod rows;
pub mod run;
