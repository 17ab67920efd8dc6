//! A tool carrier with its rotary axes at given positions: where it puts a
//! point of the workpiece and the tool tip, as the control's TCARR with
//! PAROT (CYCLE800's swivel) accounts for them (`reference/kinematics.md`
//! sections 1.2 and 2.5).
//!
//! With `R1 = R(v1, α1)`, `R2 = R(v2, α2)` (the vectors as entered, so
//! that a table's axis turns the workpiece by them) and `W` a point of the
//! workpiece in the unswivelled workpiece system, the machine places the
//! reference point of the tool holder at
//!
//! ```text
//! head  (T):  W                          + l1 + R1 (l2 + R2 (l3 + L))
//! table (P):  R1 R2 W + [l2 + R1 (l3 + R2 l4)] − (l2 + l3 + l4)  + L
//! mixed (M):  R2 W    + [l3 + R2 l4] − (l3 + l4)  + l1 + R1 (l2 + L)
//! ```
//!
//! `L` the tool's length vector (tip to holder), the offset vectors
//! pointing from the tool tip toward the machine (a head: l3 adapter to
//! axis 2, l2 axis 2 to axis 1, l1 the closure; a table: l2 machine zero
//! to axis 1, l3 axis 1 to axis 2, l4 the closure). At zero angles a closed
//! chain leaves `W + L`. The table's bracket is the zero-point shift the
//! W1 manual's example gives (l4 = (0, 0, 15) at B45: X +10.607,
//! Z −4.393), [`crate::kinematics::swivel::Swivel::shift`].

use nalgebra::{Rotation3, Vector3};

use crate::kinematics::record::{Kinematics, Record};
use crate::kinematics::swivel::{model, shift_of_turns, turn};

/// The carrier's motion at one set of axis positions, as an affine map.
#[derive(Clone, Debug, PartialEq)]
pub struct Carrier {
    /// How the axes turn the workpiece (a table's `R1 R2`, a mixed
    /// machine's `R2`; the identity for a head).
    pub part: Rotation3<f64>,
    /// Where the turning moves the workpiece's zero.
    pub part_shift: Vector3<f64>,
    /// How the axes turn the tool (a head's `R1 R2`, a mixed machine's `R1`;
    /// the identity for a table).
    pub tool: Rotation3<f64>,
    /// The head's offset vectors as the axes turn them (zero when closed
    /// and at zero angles).
    pub head: Vector3<f64>,
}

impl Carrier {
    /// The carrier of `record` with its axes at the machine `positions`
    /// (degrees, the offsets `$TC_CARR24/25` included).
    pub fn at(record: &Record, positions: [f64; 2]) -> Carrier {
        let angles = model(record, positions);
        let (r1, r2) = (turn(record, 0, angles), turn(record, 1, angles));
        let [l1, l2, l3, _] = record.offsets;
        let part_shift = shift_of_turns(record, r1, r2);
        match record.kinematics {
            Kinematics::Head => Carrier {
                part: Rotation3::identity(),
                part_shift,
                tool: r1 * r2,
                head: l1 + r1 * (l2 + r2 * l3),
            },
            Kinematics::Table => Carrier {
                part: r1 * r2,
                part_shift,
                tool: Rotation3::identity(),
                head: Vector3::zeros(),
            },
            Kinematics::Mixed => Carrier {
                part: r2,
                part_shift,
                tool: r1,
                head: l1 + r1 * l2,
            },
        }
    }

    /// The holder's reference point (the linear axes' machine position) that
    /// puts the tip of a tool of length vector `length` on the workpiece's
    /// point `part_point`.
    pub fn machine(&self, part_point: Vector3<f64>, length: Vector3<f64>) -> Vector3<f64> {
        self.part * part_point + self.part_shift + self.tool * length + self.head
    }

    /// The workpiece's point the tool tip is on with the holder at `machine`:
    /// [`Self::machine`] undone.
    pub fn part_point(&self, machine: Vector3<f64>, length: Vector3<f64>) -> Vector3<f64> {
        self.part.inverse() * (machine - self.part_shift - self.tool * length - self.head)
    }

    /// The tool's direction (tip to holder) in the workpiece's system.
    pub fn tool_direction(&self) -> Vector3<f64> {
        self.part.inverse() * (self.tool * Vector3::z())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::record::RotaryAxis;

    fn record(kinematics: Kinematics, axes: [RotaryAxis; 2], offsets: [[f64; 3]; 4]) -> Record {
        Record {
            number: 1,
            name: "TC1".into(),
            kinematics,
            offsets: offsets.map(Vector3::from),
            axes,
            options: 0,
            direction_axis: None,
        }
    }

    /// The W1 manual's table (Function Manual W1, tool carrier example): l4 =
    /// (0, 0, 15) about B at 45° shifts the zero by X +10.607, Z −4.393.
    #[test]
    fn the_manuals_table_shifts_the_zero_as_it_says() {
        let table = record(
            Kinematics::Table,
            [
                RotaryAxis::along("A", [1.0, 0.0, 0.0]),
                RotaryAxis::along("B", [0.0, 1.0, 0.0]),
            ],
            [[0.0; 3], [0.0, 0.0, -15.0], [0.0; 3], [0.0, 0.0, 15.0]],
        );
        let carrier = Carrier::at(&table, [0.0, 45.0]);
        let shift = carrier.part_shift;
        assert!((shift.x - 15.0 * 45f64.to_radians().sin()).abs() < 1e-12);
        assert!((shift.z + 15.0 * (1.0 - 45f64.to_radians().cos())).abs() < 1e-12);
        assert!(shift.y.abs() < 1e-12);
    }

    /// A head's chain, closed: at zero it adds the tool alone; turned, the
    /// holder lies along the turned tool from the tip, the pivot offsets
    /// turned with it; and `part_point` undoes `machine`.
    #[test]
    fn a_head_turns_the_tool_about_its_pivots() {
        let head = record(
            Kinematics::Head,
            [
                RotaryAxis::along("C", [0.0, 0.0, 1.0]),
                RotaryAxis::along("A", [1.0, 0.0, 0.0]),
            ],
            [
                [0.0, 0.0, -300.0],
                [0.0, 0.0, 100.0],
                [0.0, 0.0, 200.0],
                [0.0; 3],
            ],
        );
        let length = Vector3::new(0.0, 0.0, 50.0);
        let point = Vector3::new(10.0, 20.0, 30.0);
        let at_zero = Carrier::at(&head, [0.0, 0.0]);
        assert!((at_zero.machine(point, length) - (point + length)).norm() < 1e-12);
        // A at 90°: the tool (Z) turns onto −Y; the pivot of A lies 200 + 50
        // from the tip along the tool, the pivot of C 100 above it, the
        // holder's reference 300 below that.
        let turned = Carrier::at(&head, [0.0, 90.0]);
        let holder = turned.machine(point, length);
        let expected = point + Vector3::new(0.0, -250.0, 100.0 - 300.0);
        assert!((holder - expected).norm() < 1e-9, "{holder} != {expected}");
        assert!((turned.part_point(holder, length) - point).norm() < 1e-9);
        assert!((turned.tool_direction() - Vector3::new(0.0, -1.0, 0.0)).norm() < 1e-12);
    }
}
