//! From measurements to rotations: a face probed on the machine to the
//! rotation that turns the tool normal to it (face.rs), a point measured
//! before and after a rotary axis turned to the axis it turned about (the
//! Rodrigues inverse problem, turn.rs), measured positions of one point to
//! the axis and a point on it (circle.rs).
//!
//! Pure math beside `rotation` and `kinematics`, on nalgebra: no syntax, no
//! printing, no units (lengths are in whatever unit the points are given,
//! angles in degrees). It does not fit noisy data in the least-squares sense:
//! each form takes the points it is given as exact and says, with a
//! tolerance, when they do not fit one face or one turn.

pub mod circle;
pub mod face;
pub mod turn;
