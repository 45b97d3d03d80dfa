//! Contacts: the flat punch (one spring), power-law profiles and tabulated
//! profiles by the method of dimensionality reduction, and [`shape::Shape`].
pub mod flat;
pub mod mdr;
pub mod profile;
pub mod shape;
