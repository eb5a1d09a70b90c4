//! The leaf layer every other module may use: budgets and limits, seeded
//! random streams (and Structure Synth's Mersenne Twister), similarity frames, primitive kinds, colour quantisation, request parameter
//! values, source positions and diagnostics, and the embedded grammar
//! library. Nothing here knows about languages, scenes or formats.

pub mod budget;
pub mod choice;
pub mod diagnostic;
pub mod frame;
pub mod hugepages;
pub mod library;
pub mod memprobe;
pub mod mtrand;
pub mod parallel;
pub mod param;
pub mod primitive;
pub mod quantise;
pub mod rng;
pub mod timing;

pub use budget::{Budget, DeadlineStop, Limit, LimitExceeded, Limits, OnLimit};
pub use choice::Choice;
pub use diagnostic::{Diagnostic, ParseError, Severity, Span};
pub use frame::Frame;
pub use param::ParamValue;
pub use primitive::PrimitiveKind;
