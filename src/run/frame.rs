//! Where a programmed point lies on the machine: the chain of frames from
//! the workpiece (WCS) to the machine (MCS) as the control builds it
//! (Siemens, SINUMERIK 840D sl Job Planning, "Frames"): the programmable
//! frame (TRANS, ATRANS, ROT, AROT) inside the settable frame (G54 ..
//! G599, `$P_UIFR`), then the tool's length along the infeed axis of the
//! plane. A frame moves a point by its mirror, scale and rotation, then its
//! translation: `parent = T + R · S · M · child` (the order of a frame's
//! components in Job Planning, "Frames": translation, rotation, scaling,
//! mirroring), the linear part kept as one matrix. Base frames are not read (the machine data
//! hold them where a machine uses them; said in the run's assumptions).

use nalgebra::{Matrix3, Rotation3, Vector3};

/// One frame over the run's axes: a translation per axis (the geometry
/// axes first) and the rotation, scale and mirror of the geometry axes as
/// one matrix.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub translation: Vec<f64>,
    pub linear: Matrix3<f64>,
}

impl Frame {
    pub fn identity(axes: usize) -> Frame {
        Frame {
            translation: vec![0.0; axes],
            linear: Matrix3::identity(),
        }
    }

    /// `point` (the run's axes, geometry first) in the frame's parent;
    /// `None` where a coordinate it needs is unknown.
    pub fn apply(&self, point: &[Option<f64>]) -> Vec<Option<f64>> {
        let mut out: Vec<Option<f64>> = point
            .iter()
            .zip(&self.translation)
            .map(|(p, t)| p.map(|p| p + t))
            .collect();
        if self.linear != Matrix3::identity() {
            let geometry = (point[0], point[1], point[2]);
            let rotated = match geometry {
                (Some(x), Some(y), Some(z)) => {
                    let r = self.linear * Vector3::new(x, y, z);
                    [Some(r.x), Some(r.y), Some(r.z)]
                }
                _ => [None, None, None],
            };
            for (k, value) in rotated.into_iter().enumerate() {
                out[k] = value.map(|v| v + self.translation[k]);
            }
        }
        out
    }

    /// The linear part applied to a direction of the geometry axes.
    pub fn turn(&self, direction: Vector3<f64>) -> Vector3<f64> {
        self.linear * direction
    }

    /// `point` (the run's axes) of the frame's parent in the frame; `None`
    /// where a coordinate it needs is unknown, or all three geometry axes
    /// where the frame cannot be undone (a scale of 0).
    pub fn undo(&self, point: &[Option<f64>]) -> Vec<Option<f64>> {
        let mut out: Vec<Option<f64>> = point
            .iter()
            .zip(&self.translation)
            .map(|(p, t)| p.map(|p| p - t))
            .collect();
        if self.linear != Matrix3::identity() {
            let back = self.linear.try_inverse();
            let geometry = match (back, out[0], out[1], out[2]) {
                (Some(back), Some(x), Some(y), Some(z)) => {
                    let r = back * Vector3::new(x, y, z);
                    [Some(r.x), Some(r.y), Some(r.z)]
                }
                _ => [None, None, None],
            };
            out[..3].copy_from_slice(&geometry);
        }
        out
    }

    /// This frame with `child` chained inside it (the control's `self :
    /// child`): a point of the child's system goes through both.
    pub fn then(&self, child: &Frame) -> Frame {
        let inner = Vector3::new(
            child.translation[0],
            child.translation[1],
            child.translation[2],
        );
        let turned = self.linear * inner;
        let mut translation: Vec<f64> = self
            .translation
            .iter()
            .zip(&child.translation)
            .map(|(a, b)| a + b)
            .collect();
        for (k, shift) in turned.iter().enumerate() {
            translation[k] = self.translation[k] + shift;
        }
        Frame {
            translation,
            linear: self.linear * child.linear,
        }
    }

    /// Whether the frame mixes the geometry axes (a rotation): one of them
    /// programmed then moves them all.
    pub fn couples(&self) -> bool {
        (0..3).any(|r| (0..3).any(|c| r != c && self.linear[(r, c)] != 0.0))
    }
}

/// The rotation `ROT X=a Y=b Z=c` gives under RPY angles (MD10600 = 1):
/// about Z, then the new Y, then the new X (degrees).
pub fn rpy(angles: [f64; 3]) -> Matrix3<f64> {
    let [a, b, c] = angles.map(f64::to_radians);
    (Rotation3::from_axis_angle(&Vector3::z_axis(), c)
        * Rotation3::from_axis_angle(&Vector3::y_axis(), b)
        * Rotation3::from_axis_angle(&Vector3::x_axis(), a))
    .into_inner()
}

/// A scale of each geometry axis, a mirror where `mirrored` (`SCALE`,
/// `MIRROR`, a frame's `SC` and `MI`).
pub fn scale_mirror(scale: [f64; 3], mirrored: [bool; 3]) -> Matrix3<f64> {
    let sign = |m: bool| if m { -1.0 } else { 1.0 };
    Matrix3::from_diagonal(&Vector3::new(
        scale[0] * sign(mirrored[0]),
        scale[1] * sign(mirrored[1]),
        scale[2] * sign(mirrored[2]),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_frame_turns_then_shifts() {
        let frame = Frame {
            translation: vec![100.0, 0.0, 0.0, 5.0],
            linear: rpy([0.0, 0.0, 90.0]),
        };
        let out = frame.apply(&[Some(10.0), Some(0.0), Some(0.0), Some(1.0)]);
        let out: Vec<f64> = out.into_iter().map(|v| v.expect("known")).collect();
        assert!(
            (out[0] - 100.0).abs() < 1e-12 && (out[1] - 10.0).abs() < 1e-12,
            "{out:?}"
        );
        assert_eq!(out[3], 6.0);
        let unknown = frame.apply(&[None, Some(0.0), Some(0.0), Some(1.0)]);
        assert_eq!(unknown[..3], [None, None, None]);
    }

    #[test]
    fn a_chained_frame_is_both_applied_in_turn() {
        let outer = Frame {
            translation: vec![100.0, 0.0, 0.0, 5.0],
            linear: rpy([0.0, 0.0, 90.0]),
        };
        let inner = Frame {
            translation: vec![0.0, 10.0, 3.0, 1.0],
            linear: rpy([30.0, 0.0, 0.0]),
        };
        let point = [Some(1.0), Some(2.0), Some(3.0), Some(4.0)];
        let chained = outer.then(&inner).apply(&point);
        let in_turn = outer.apply(&inner.apply(&point));
        for (a, b) in chained.iter().zip(&in_turn) {
            assert!(
                (a.expect("known") - b.expect("known")).abs() < 1e-12,
                "{chained:?} != {in_turn:?}"
            );
        }
    }
}
