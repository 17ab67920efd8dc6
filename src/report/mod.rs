//! What a call comes to, in words and as JSON, for the command line and the
//! editor alike: a CYCLE600's evaluation ([`call`]) and where a swivel takes
//! the machine's axes ([`swivel`]). It words what `semantic`, `kinematics`
//! and `emit` computed; it prints nothing itself.

pub mod call;
pub mod swivel;
