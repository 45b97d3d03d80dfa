//! What the solver reports about one point beside the ratio
//! ([`crate::Shape::report`]): the flat punch's regime and events, a power
//! law's bands, the phases and bands under a tangential oscillation, and the
//! contact regime of a shape.
pub use crate::contact::combined::{Combined, CombinedBand, SpringReport, StopEvent, Tangential};
pub use crate::contact::flat::FlatPoint;
pub use crate::contact::mdr::{Band, BandKind, MdrPoint, MdrResult};
pub use crate::contact::regime::ContactRegime;
