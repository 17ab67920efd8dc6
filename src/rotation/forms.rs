//! The other ways a rotation or a whole frame is written: quaternion,
//! axis and angle, the Gibbs / Rodrigues vector, a post-processor's
//! `ROT_MAT` / `TRANS_MAT`, and the tool-to-piece chain of two cooperating
//! structures. Each converts both ways, to and from [`Pose`].
//!
//! Pure math on nalgebra; reading and writing the text of each form is the
//! command line's. Frames are rigid: scaling and mirroring have no form here.

use nalgebra::{IsometryMatrix3, Matrix3, Rotation3, Translation3, UnitQuaternion, Vector3};

use crate::rotation::euler::{decompose, matrix, Decomposition};
use crate::rotation::sequence::{Axis, Kind, Sequence};
use crate::rotation::trig::{atan2_degrees, sin_cos_degrees};

/// A whole frame: the new system's axes (the rotation's columns) and origin
/// in the old one. A point given in the new system lies at
/// `rotation · p + translation` in the old; as CYCLE800's frame with
/// `X0 Y0 Z0` and `X1 Y1 Z1` 0, or `TRANS` followed by `AROT`.
pub type Pose = IsometryMatrix3<f64>;

/// The frame of a translation and a rotation.
pub fn pose(translation: Vector3<f64>, rotation: Rotation3<f64>) -> Pose {
    IsometryMatrix3::from_parts(Translation3::from(translation), rotation)
}

/// Why numbers are no rotation.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FormError {
    #[error("not a rotation matrix: its rows and columns are not orthonormal (off by {0:e})")]
    NotOrthonormal(f64),
    #[error("not a rotation matrix: its determinant is {0}, a mirror image")]
    Mirror(f64),
    #[error("not a frame matrix: its last row is not 0 0 0 1")]
    LastRow,
    #[error("a quaternion of length {0} is no rotation")]
    ZeroQuaternion(f64),
    #[error("the axis is the zero vector, which turns about nothing by {0}°")]
    ZeroAxis(f64),
    #[error("a half turn has no Gibbs vector: 2 tan(180°/2) is infinite")]
    HalfTurn,
}

/// How far a matrix may be from orthonormal and still be read as a
/// rotation: six printed decimals are off by up to 5e-7.
pub const ORTHONORMAL_TOLERANCE: f64 = 1e-6;

/// The rotation of a 3x3 matrix (rows), which must be one within
/// [`ORTHONORMAL_TOLERANCE`]; a nearly orthonormal one is replaced by the
/// nearest rotation (the polar factor), an exact one kept bit for bit.
pub fn rotation_of_matrix(m: &Matrix3<f64>) -> Result<Rotation3<f64>, FormError> {
    let off = (m.transpose() * m - Matrix3::identity()).abs().max();
    if off.is_nan() || off > ORTHONORMAL_TOLERANCE {
        return Err(FormError::NotOrthonormal(off));
    }
    let determinant = m.determinant();
    if determinant < 0.0 {
        return Err(FormError::Mirror(determinant));
    }
    if off <= 4.0 * f64::EPSILON {
        return Ok(Rotation3::from_matrix_unchecked(*m));
    }
    let svd = m.svd(true, true);
    match (svd.u, svd.v_t) {
        (Some(u), Some(v_t)) => Ok(Rotation3::from_matrix_unchecked(u * v_t)),
        _ => Err(FormError::NotOrthonormal(off)),
    }
}

/// A frame from its 4x4 matrix (rows), `[R t; 0 0 0 1]`.
pub fn pose_of_matrix(rows: &[[f64; 4]; 4]) -> Result<Pose, FormError> {
    if rows[3] != [0.0, 0.0, 0.0, 1.0] {
        return Err(FormError::LastRow);
    }
    let rotation = rotation_of_matrix(&Matrix3::from_fn(|r, c| rows[r][c]))?;
    let translation = Vector3::new(rows[0][3], rows[1][3], rows[2][3]);
    Ok(pose(translation, rotation))
}

/// The 4x4 matrix of a frame, rows.
pub fn matrix_of_pose(pose: &Pose) -> [[f64; 4]; 4] {
    let m = pose.to_homogeneous();
    [0, 1, 2, 3].map(|r| [0, 1, 2, 3].map(|c| m[(r, c)] + 0.0))
}

/// The unit quaternion `[w, x, y, z]` of a rotation, `w >= 0` (of the two
/// that describe it, `q` and `-q`, the one turning by at most 180°).
pub fn quaternion(rotation: &Rotation3<f64>) -> [f64; 4] {
    let q = UnitQuaternion::from_rotation_matrix(rotation);
    let sign = if q.w < 0.0 { -1.0 } else { 1.0 };
    [q.w, q.i, q.j, q.k].map(|c| sign * c + 0.0)
}

/// The rotation of a quaternion `[w, x, y, z]` of any length but 0.
pub fn from_quaternion([w, x, y, z]: [f64; 4]) -> Result<Rotation3<f64>, FormError> {
    let q = nalgebra::Quaternion::new(w, x, y, z);
    let norm = q.norm();
    if !(norm > 0.0 && norm.is_finite()) {
        return Err(FormError::ZeroQuaternion(norm));
    }
    Ok(UnitQuaternion::from_quaternion(q).to_rotation_matrix())
}

/// The unit axis and the angle (degrees, in [0, 180]) of a rotation, from
/// its quaternion, which is well conditioned everywhere (at a half turn
/// too, where the matrix's antisymmetric part vanishes). The identity turns
/// 0° about +Z.
pub fn axis_angle(rotation: &Rotation3<f64>) -> (Vector3<f64>, f64) {
    let [w, x, y, z] = quaternion(rotation);
    let v = Vector3::new(x, y, z);
    let sine = v.norm();
    if sine == 0.0 {
        return (Vector3::z(), 0.0);
    }
    (v / sine, 2.0 * atan2_degrees(sine, w))
}

/// The rotation about `axis` (any length) by `degrees`; the zero axis only
/// with a whole number of turns (the identity).
pub fn from_axis_angle(axis: Vector3<f64>, degrees: f64) -> Result<Rotation3<f64>, FormError> {
    let length = axis.norm();
    if length == 0.0 || !length.is_finite() {
        if crate::rotation::euler::wrap(degrees) == 0.0 {
            return Ok(Rotation3::identity());
        }
        return Err(FormError::ZeroAxis(degrees));
    }
    let (s, c) = sin_cos_degrees(degrees / 2.0);
    let v = axis / length * s;
    Ok(
        UnitQuaternion::from_quaternion(nalgebra::Quaternion::new(c, v.x, v.y, v.z))
            .to_rotation_matrix(),
    )
}

/// The Gibbs / Rodrigues vector `θ = 2 tan(χ/2) e` of a rotation by χ
/// about the unit axis e (the finite rotation vector of the Rodrigues
/// equation, seed 002): `2 v / w` of the quaternion. None for a half turn.
pub fn gibbs(rotation: &Rotation3<f64>) -> Result<Vector3<f64>, FormError> {
    let [w, x, y, z] = quaternion(rotation);
    if w == 0.0 {
        return Err(FormError::HalfTurn);
    }
    let g = Vector3::new(x, y, z) * (2.0 / w);
    if g.iter().all(|c| c.is_finite()) {
        Ok(g.map(|c| c + 0.0))
    } else {
        Err(FormError::HalfTurn)
    }
}

/// Where the rotation of Gibbs vector `theta` takes `rho`, by the Rodrigues
/// formula as the seed writes it (002, eq. 1):
/// `ρ' = ρ + 1 / (1 + |θ|²/4) · θ × (ρ + ½ θ × ρ)`.
pub fn rotate_by_gibbs(theta: &Vector3<f64>, rho: &Vector3<f64>) -> Vector3<f64> {
    let scale = 1.0 / (1.0 + theta.norm_squared() / 4.0);
    rho + theta.cross(&(rho + theta.cross(rho) / 2.0)) * scale
}

/// The rotation of a Gibbs vector: its columns are where the formula
/// takes the unit vectors.
pub fn from_gibbs(theta: &Vector3<f64>) -> Result<Rotation3<f64>, FormError> {
    // Past about 1e154 |θ|² overflows: a half turn, to the last bit.
    if !theta.norm_squared().is_finite() {
        return Err(FormError::HalfTurn);
    }
    let columns = [Vector3::x(), Vector3::y(), Vector3::z()].map(|e| rotate_by_gibbs(theta, &e));
    rotation_of_matrix(&Matrix3::from_columns(&columns))
}

/// A CAM post-processor's `ROT_MAT1..9` (row by row) and `TRANS_MATX..Z`
/// (seed 001), which map a point's coordinates as
/// `p_out = ROT_MAT · p_in + TRANS_MAT`.
///
/// The seed's three single-axis examples do not agree read one way: read
/// row by row, its Y and Z matrices are `R_Y(A)ᵀ` and `R_Z(A)ᵀ` of the
/// right-hand angle A, its X matrix `R_X(A)` untransposed. Its own worked
/// numbers decide: the 4-axis angle is `A = ATAN2(I_ORIGIN, K_ORIGIN)` and
/// becomes YROTATION, the right-hand angle about Y that turns +Z onto the
/// origin's axis (I, 0, K); the Y matrix with that A takes (I, 0, K) back
/// onto +Z, which is what "all coordinates are multiplied by that matrix
/// before sending to the post" needs. So `ROT_MAT` is the transpose of the
/// frame rotation: it gives a point's coordinates in the rotated system.
/// The X example fits the same reading only with its angle ATAN(J/K) taken
/// as a left-hand angle (the right-hand one is ATAN2(-J, K)), the sign slip
/// the Y and Z examples do not have. The translation: "the distance between
/// the origin and the rotation axis, rotated by the matrix" (and, with no
/// rotation, `X_ORIGIN - FIRSTX`), i.e. `TRANS_MAT = ROT_MAT · d` with d the
/// old origin seen from the new one, `-translation`. Together `p_out` are
/// the coordinates in the frame of the point at `p_in` in the old system:
/// the post's map is the frame's inverse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PostMatrix {
    /// `ROT_MAT1..9`, row by row.
    pub rot_mat: [f64; 9],
    /// `TRANS_MATX`, `TRANS_MATY`, `TRANS_MATZ`.
    pub trans_mat: [f64; 3],
}

impl PostMatrix {
    pub fn of(pose: &Pose) -> PostMatrix {
        let inverse = pose.inverse();
        let m = inverse.rotation.matrix();
        let t = inverse.translation.vector;
        PostMatrix {
            rot_mat: std::array::from_fn(|i| m[(i / 3, i % 3)] + 0.0),
            trans_mat: [t.x + 0.0, t.y + 0.0, t.z + 0.0],
        }
    }

    pub fn pose(&self) -> Result<Pose, FormError> {
        let m = Matrix3::from_fn(|r, c| self.rot_mat[3 * r + c]);
        let rotation = rotation_of_matrix(&m)?;
        let [x, y, z] = self.trans_mat;
        Ok(pose(Vector3::new(x, y, z), rotation).inverse())
    }
}

/// The tool-to-piece frame of two cooperating structures (seed 004, eq. 1):
/// `T_SP = T_PO⁻¹ · T_SO`, the tool system S seen from the piece system P,
/// with `tool` = T_SO and `piece` = T_PO both given in the fixed system O.
/// (The seed calls `T_PO⁻¹` the transposed matrix: for a frame with a
/// translation it is the inverse, which transposes the rotation only.)
pub fn tool_to_piece(tool: &Pose, piece: &Pose) -> Pose {
    piece.inverse() * tool
}

/// The seed's order of the tool-to-piece chain (004, eq. 3, 11):
/// `R_SP = R(α_zS; β_xS; γ_yS) = R_Z(α) · R_X(β) · R_Y(γ)`, the intrinsic
/// Z, X', Y'' sequence (`_MODE` 39).
pub fn chain_sequence() -> Sequence {
    Sequence {
        axes: [Axis::Z, Axis::X, Axis::Y],
        kind: Kind::Intrinsic,
    }
}

/// The angles of `rotation` in the seed's chain order.
pub fn chain_angles(rotation: &Rotation3<f64>) -> Decomposition {
    decompose(chain_sequence(), rotation)
}

/// The frame of a position and the seed's three chain angles.
pub fn from_chain(position: Vector3<f64>, [alpha, beta, gamma]: [f64; 3]) -> Pose {
    pose(position, matrix(chain_sequence(), [alpha, beta, gamma]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::frame;

    fn seq(text: &str) -> Sequence {
        text.parse().expect("valid")
    }

    fn close(a: &Matrix3<f64>, b: &Matrix3<f64>, tolerance: f64) -> bool {
        (a - b).abs().max() < tolerance
    }

    /// The seed's unit matrix: the identity, no translation.
    #[test]
    fn post_matrix_of_the_identity_is_the_seeds_unit_matrix() {
        let post = PostMatrix::of(&Pose::identity());
        assert_eq!(post.rot_mat, [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]);
        assert_eq!(post.trans_mat, [0.0; 3]);
    }

    /// The seed's Y and Z matrices are those of the right-hand angle A; its X
    /// matrix is that of -A (the sign slip of its X example).
    #[test]
    fn post_matrix_gives_the_seeds_single_axis_matrices() {
        for a in [30.0, -72.5, 135.0] {
            let (s, c) = sin_cos_degrees(a);
            let rot = |sequence: &str| {
                PostMatrix::of(&pose(
                    Vector3::zeros(),
                    matrix(seq(sequence), [a, 0.0, 0.0]),
                ))
                .rot_mat
            };
            // ROT_MAT1..9 as the seed writes them for "rotation around Y / Z axis".
            assert_eq!(
                rot("e:YXZ"),
                [c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c].map(|v| v + 0.0)
            );
            assert_eq!(
                rot("e:ZXY"),
                [c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0].map(|v| v + 0.0)
            );
            let x_of_minus_a = PostMatrix::of(&pose(
                Vector3::zeros(),
                matrix(seq("e:XYZ"), [-a, 0.0, 0.0]),
            ))
            .rot_mat;
            assert_eq!(
                x_of_minus_a,
                [1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c].map(|v| v + 0.0)
            );
        }
    }

    /// The seed's worked 4-axis example: `A = ATAN2(I_ORIGIN, K_ORIGIN)` is
    /// YROTATION, and the matrix takes the origin's axis (I, 0, K) onto +Z.
    #[test]
    fn post_matrix_takes_the_origins_axis_onto_z_as_the_worked_example() {
        let (i, k) = (0.3f64, 0.8f64);
        let a = atan2_degrees(i, k);
        let frame = pose(Vector3::zeros(), matrix(seq("e:YXZ"), [a, 0.0, 0.0]));
        let post = PostMatrix::of(&frame);
        let m = Matrix3::from_row_slice(&post.rot_mat);
        let axis = Vector3::new(i, 0.0, k).normalize();
        assert!((m * axis - Vector3::z()).abs().max() < 1e-15);
    }

    /// "The translation: the distance between the origin and the rotation
    /// axis, rotated by the matrix"; with no rotation, `X_ORIGIN - FIRSTX`.
    #[test]
    fn post_translation_is_the_distance_rotated_by_the_matrix() {
        let origin_change =
            PostMatrix::of(&pose(Vector3::new(-5.0, 2.0, 7.0), Rotation3::identity()));
        assert_eq!(origin_change.trans_mat, [5.0, -2.0, -7.0]);
        let rotation = matrix(seq("e:XYZ"), [10.0, 20.0, 30.0]);
        let t = Vector3::new(1.0, -2.0, 3.0);
        let post = PostMatrix::of(&pose(t, rotation));
        let m = Matrix3::from_row_slice(&post.rot_mat);
        let expected = m * -t;
        assert!((Vector3::from(post.trans_mat) - expected).abs().max() < 1e-14);
        let back = post.pose().expect("a rotation");
        assert!((back.translation.vector - t).abs().max() < 1e-14);
        assert!(close(back.rotation.matrix(), rotation.matrix(), 1e-15));
    }

    /// The Rodrigues formula of seed 002 against the matrix form
    /// `R = I + sin χ K + (1 - cos χ) K²`.
    #[test]
    fn rodrigues_vector_formula_agrees_with_the_matrix_form() {
        let axis = Vector3::new(1.0, -2.0, 0.5).normalize();
        for chi in [0.0, 1e-9, 30.0, 90.0, 179.0, -120.0] {
            let (s, c) = sin_cos_degrees(chi / 2.0);
            let theta = axis * (2.0 * s / c);
            let by_matrix = frame::from_axis_angle(axis, chi);
            let rho = Vector3::new(3.0, 4.0, -5.0);
            let rotated = rotate_by_gibbs(&theta, &rho);
            assert!((rotated - by_matrix * rho).abs().max() < 1e-12, "{chi}");
            let from = from_gibbs(&theta).expect("a rotation");
            assert!(close(from.matrix(), by_matrix.matrix(), 1e-13), "{chi}");
        }
    }

    #[test]
    fn gibbs_vector_is_two_tan_half_the_angle_along_the_axis() {
        let rotation = frame::from_axis_angle(Vector3::z(), 90.0);
        let g = gibbs(&rotation).expect("not a half turn");
        assert!((g - Vector3::new(0.0, 0.0, 2.0)).abs().max() < 1e-15);
        assert_eq!(
            gibbs(&frame::from_axis_angle(Vector3::x(), 180.0)),
            Err(FormError::HalfTurn)
        );
    }

    #[test]
    fn axis_angle_at_a_half_turn_and_at_the_identity() {
        let axis = Vector3::new(0.0, 3.0, 4.0) / 5.0;
        let (found, angle) = axis_angle(&frame::from_axis_angle(axis, 180.0));
        assert!((angle - 180.0).abs() < 1e-12);
        assert!((found - axis).abs().max() < 1e-15 || (found + axis).abs().max() < 1e-15);
        assert_eq!(axis_angle(&Rotation3::identity()), (Vector3::z(), 0.0));
        assert_eq!(
            from_axis_angle(Vector3::zeros(), 360.0),
            Ok(Rotation3::identity())
        );
        assert!(from_axis_angle(Vector3::zeros(), 10.0).is_err());
    }

    #[test]
    #[allow(clippy::approx_constant)] // the paper's matrix, printed to 4 decimals
    fn quaternions_of_any_length_and_matrices_near_rotations() {
        let q = quaternion(&frame::from_axis_angle(Vector3::y(), 60.0));
        let scaled = from_quaternion(q.map(|c| c * -3.0)).expect("a rotation");
        assert!(close(
            scaled.matrix(),
            frame::from_axis_angle(Vector3::y(), 60.0).matrix(),
            1e-15
        ));
        assert_eq!(
            from_quaternion([0.0; 4]),
            Err(FormError::ZeroQuaternion(0.0))
        );
        // The paper's matrix, printed to 4 decimals, is no rotation; to 7 it is.
        let printed = Matrix3::new(
            0.3536, -0.5732, 0.7392, 0.6124, 0.7392, 0.2803, -0.7071, 0.3536, 0.6124,
        );
        assert!(matches!(
            rotation_of_matrix(&printed),
            Err(FormError::NotOrthonormal(_))
        ));
        let exact = matrix(seq("e:XYZ"), [30.0, 45.0, 60.0]);
        let rounded = exact.matrix().map(|v| (v * 1e7).round() / 1e7);
        let nearest = rotation_of_matrix(&rounded).expect("near a rotation");
        assert!(close(nearest.matrix(), exact.matrix(), 1e-7));
        assert!(
            (nearest.matrix().transpose() * nearest.matrix() - Matrix3::identity())
                .abs()
                .max()
                < 1e-15
        );
        let mirror = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
        assert!(matches!(
            rotation_of_matrix(&mirror),
            Err(FormError::Mirror(_))
        ));
    }

    /// Seed 004's orientation matrix (eq. 3) is R_Z(α) R_X(β) R_Y(γ); its
    /// inverse equations (11) read β from T21, γ from T20/T22, α from T01/T11.
    #[test]
    fn chain_angles_follow_the_seeds_matrix() {
        let (alpha, beta, gamma) = (25.0, -40.0, 70.0);
        let r = matrix(chain_sequence(), [alpha, beta, gamma]);
        let m = r.matrix();
        let (sa, ca) = sin_cos_degrees(alpha);
        let (sb, cb) = sin_cos_degrees(beta);
        let (sg, cg) = sin_cos_degrees(gamma);
        let seed = Matrix3::new(
            -sa * sb * sg + ca * cg,
            -sa * cb,
            sa * sb * cg + ca * sg,
            ca * sb * sg + sa * cg,
            ca * cb,
            -ca * sb * cg + sa * sg,
            -cb * sg,
            sb,
            cb * cg,
        );
        assert!(close(m, &seed, 1e-15));
        assert!((m[(2, 1)] - sb).abs() < 1e-15);
        let d = chain_angles(&r);
        for (found, given) in d.angles.iter().zip([alpha, beta, gamma]) {
            assert!((found - given).abs() < 1e-12);
        }
    }

    /// T_SP = T_PO⁻¹ · T_SO: a point fixed to the tool, seen from the piece.
    #[test]
    fn tool_to_piece_sees_the_tool_from_the_piece() {
        let tool = pose(
            Vector3::new(100.0, 0.0, 50.0),
            matrix(seq("i:ZYX"), [30.0, 10.0, 0.0]),
        );
        let piece = pose(
            Vector3::new(20.0, 30.0, 0.0),
            matrix(seq("i:ZYX"), [-15.0, 0.0, 5.0]),
        );
        let sp = tool_to_piece(&tool, &piece);
        let tip = nalgebra::Point3::new(0.0, 0.0, -10.0);
        let in_fixed = tool * tip;
        assert!(((piece * (sp * tip)) - in_fixed).abs().max() < 1e-12);
    }
}
