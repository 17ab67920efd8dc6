//! CYCLE600 calls whose angles (or translations) are measured at run time,
//! rewritten as native Sinumerik arithmetic that the control evaluates.
//!
//! What is known offline (sequences, flags, head) chooses the formula; the
//! generated blocks follow `rotation::euler` step for step: the matrix
//! elements from SIN/COS of the argument expressions, the middle angle by
//! ATAN2 with a square root (never ASIN), the first from a well-conditioned
//! pair, the third with the first rotation taken out, and an IF/ELSE for
//! gimbal lock that does what the offline engine does. Known angles are folded
//! into constants, so only the elements that vary are computed.

use std::collections::BTreeMap;

use nalgebra::Matrix3;

use crate::diagnostic::Diagnostic;
use crate::emit::cycle600::{Form, Options};
use crate::number::format;
use crate::registry;
use crate::rotation::euler::GIMBAL_TOLERANCE;
use crate::rotation::trig::sin_cos_degrees;
use crate::rotation::{self, Axis, Kind};
use crate::semantic::cycle600::{
    additive_onto_unknown, no_cycle800_form, Operand, RuntimeParameters,
};
use crate::semantic::env::Active;
use crate::semantic::Model;
use crate::span::Span;

/// Where the intermediate values live: local variables (`SNP_...`, declared
/// by DEF lines the rewrite inserts) or R parameters from `R<base>` upward.
#[derive(Debug, Default)]
pub struct Names {
    r_base: Option<u32>,
    allocated: Vec<String>,
}

/// The highest `--runtime-r` base taken: a control has R0 to R(n-1), n set
/// by MD28050 (hundreds or a few thousand), so a base past it is a typo;
/// it keeps the numbers the run-time code counts up from it far from
/// `u32`'s end.
pub const MAX_R_BASE: u32 = 99_999;

/// The prefix of the local variables (two letters first, as identifiers need).
pub const PREFIX: &str = "SNP_";

impl Names {
    pub fn new(r_base: Option<u32>) -> Self {
        Self {
            r_base,
            allocated: Vec::new(),
        }
    }

    /// The variable for `base` (`A1`, `M23`, ...), the same for every call.
    fn get(&mut self, base: &str) -> String {
        let index = match self.allocated.iter().position(|b| b == base) {
            Some(index) => index,
            None => {
                self.allocated.push(base.to_string());
                self.allocated.len() - 1
            }
        };
        match self.r_base {
            Some(r) => format!("R{}", r as usize + index),
            None => format!("{PREFIX}{base}"),
        }
    }

    /// The local variables to declare (none with R parameters).
    pub fn locals(&self) -> Vec<String> {
        match self.r_base {
            Some(_) => Vec::new(),
            None => self
                .allocated
                .iter()
                .map(|b| format!("{PREFIX}{b}"))
                .collect(),
        }
    }

    /// The R parameters used, as a range of numbers.
    pub fn r_range(&self) -> Option<std::ops::Range<u32>> {
        self.r_base.map(|r| r..r + self.allocated.len() as u32)
    }
}

/// A polynomial in named factors: monomial (sorted factor names) -> coefficient.
#[derive(Clone, Debug, Default, PartialEq)]
struct Poly(BTreeMap<Vec<String>, f64>);

impl Poly {
    fn constant(value: f64) -> Poly {
        let mut poly = Poly::default();
        if value != 0.0 {
            poly.0.insert(Vec::new(), value);
        }
        poly
    }

    fn var(name: String) -> Poly {
        Poly(BTreeMap::from([(vec![name], 1.0)]))
    }

    fn add(&self, other: &Poly) -> Poly {
        let mut sum = self.clone();
        for (monomial, c) in &other.0 {
            *sum.0.entry(monomial.clone()).or_insert(0.0) += c;
        }
        sum.0.retain(|_, c| c.abs() > 1e-15);
        sum
    }

    fn mul(&self, other: &Poly) -> Poly {
        let mut product = Poly::default();
        for (ma, ca) in &self.0 {
            for (mb, cb) in &other.0 {
                let mut monomial: Vec<String> = ma.iter().chain(mb).cloned().collect();
                monomial.sort();
                *product.0.entry(monomial).or_insert(0.0) += ca * cb;
            }
        }
        product.0.retain(|_, c| c.abs() > 1e-15);
        product
    }

    fn scale(&self, factor: f64) -> Poly {
        self.mul(&Poly::constant(factor))
    }

    fn as_constant(&self) -> Option<f64> {
        match self.0.len() {
            0 => Some(0.0),
            1 => self.0.get(&Vec::new()).copied(),
            _ => None,
        }
    }

    /// NC text: `SNP_C1*SNP_S2-0.5*SNP_S1`, constants with 15 decimals.
    fn render(&self) -> String {
        if self.0.is_empty() {
            return "0".to_string();
        }
        let mut text = String::new();
        for (monomial, &c) in &self.0 {
            let magnitude = format(c.abs(), 15);
            let body = match (monomial.is_empty(), magnitude.as_str()) {
                (true, _) => magnitude,
                (false, "1") => monomial.join("*"),
                (false, _) => format!("{magnitude}*{}", monomial.join("*")),
            };
            if c < 0.0 {
                text.push('-');
            } else if !text.is_empty() {
                text.push('+');
            }
            text.push_str(&body);
        }
        text
    }
}

type PolyMatrix = [[Poly; 3]; 3];

fn multiply(a: &PolyMatrix, b: &PolyMatrix) -> PolyMatrix {
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            (0..3).fold(Poly::default(), |sum, k| sum.add(&a[r][k].mul(&b[k][c])))
        })
    })
}

fn constant_matrix(m: &Matrix3<f64>) -> PolyMatrix {
    std::array::from_fn(|r| std::array::from_fn(|c| Poly::constant(m[(r, c)])))
}

/// The elemental rotation about `axis` with `sin`, `cos` given as polynomials.
fn elemental(axis: Axis, s: Poly, c: Poly) -> PolyMatrix {
    let (zero, one) = (Poly::default(), Poly::constant(1.0));
    let minus_s = s.scale(-1.0);
    match axis {
        Axis::X => [
            [one, zero.clone(), zero.clone()],
            [zero.clone(), c.clone(), minus_s],
            [zero, s, c],
        ],
        Axis::Y => [
            [c.clone(), zero.clone(), s],
            [zero.clone(), one, zero.clone()],
            [minus_s, zero, c],
        ],
        Axis::Z => [
            [c.clone(), minus_s, zero.clone()],
            [s, c, zero.clone()],
            [zero.clone(), zero, one],
        ],
    }
}

/// Collects the generated blocks, each with what it computes.
struct Code<'n> {
    names: &'n mut Names,
    blocks: Vec<String>,
}

impl Code<'_> {
    fn assign(&mut self, base: &str, value: String, what: &str) -> String {
        let name = self.names.get(base);
        self.blocks.push(format!("{name}={value} ; {what}"));
        name
    }

    /// A matrix element as an operand: itself when it is a constant or one
    /// signed factor (`-SNP_S1`), else a variable holding it.
    fn element(&mut self, poly: &Poly, row: usize, column: usize) -> Poly {
        let single_factor =
            poly.0.len() == 1 && poly.0.iter().all(|(m, c)| m.len() == 1 && c.abs() == 1.0);
        match poly.as_constant() {
            _ if single_factor => poly.clone(),
            Some(_) => poly.clone(),
            None => Poly::var(self.assign(
                &format!("M{}{}", row + 1, column + 1),
                poly.render(),
                &format!("rotation matrix, row {} column {}", row + 1, column + 1),
            )),
        }
    }
}

/// The blocks replacing a call whose coordinates are partly known only at
/// run time. Fails (with the diagnostic) where the offline rewrite would.
pub fn code(
    p: &RuntimeParameters,
    active: &Active,
    needs_stopre: bool,
    options: &Options,
    names: &mut Names,
    span: Span,
) -> Result<Vec<String>, Diagnostic> {
    let mut code = Code {
        names,
        blocks: Vec::new(),
    };
    if needs_stopre {
        code.blocks
            .push("STOPRE ; the measured values must be final before they are read".to_string());
    }

    // The input rotation, from SIN/COS of the run-time angles.
    let mut factors: Vec<(Poly, Poly)> = Vec::with_capacity(3);
    for n in 0..3 {
        factors.push(match &p.coordinates[3 + n] {
            Operand::Known(degrees) => {
                let (s, c) = sin_cos_degrees(*degrees);
                (Poly::constant(s), Poly::constant(c))
            }
            Operand::Runtime(text) => {
                let s = code.assign(
                    &format!("S{}", n + 1),
                    format!("SIN({text})"),
                    &format!("sine of _ANG_{}", n + 1),
                );
                let c = code.assign(
                    &format!("C{}", n + 1),
                    format!("COS({text})"),
                    &format!("cosine of _ANG_{}", n + 1),
                );
                (Poly::var(s), Poly::var(c))
            }
        });
    }
    let [a, b, c] = p.input.axes;
    let e = |axis: Axis, n: usize| elemental(axis, factors[n].0.clone(), factors[n].1.clone());
    let own = match p.input.kind {
        Kind::Intrinsic => multiply(&multiply(&e(a, 0), &e(b, 1)), &e(c, 2)),
        Kind::Extrinsic => multiply(&multiply(&e(c, 2), &e(b, 1)), &e(a, 0)),
    };

    // Additive: composed with the active rotation when it is known offline.
    let (target, additive_on_control) = if p.additive {
        match active.rotation() {
            Some(active) => {
                let r0 = constant_matrix(active.matrix());
                match p.input.kind {
                    Kind::Intrinsic => (multiply(&r0, &own), false),
                    Kind::Extrinsic => (multiply(&own, &r0), false),
                }
            }
            None if p.input.kind == Kind::Intrinsic => (own, true),
            None => {
                return Err(additive_onto_unknown(
                    span,
                    "an additive extrinsic rotation",
                    "",
                ));
            }
        }
    } else {
        (own, false)
    };
    if p.recalculate_only && additive_on_control {
        return Err(additive_onto_unknown(
            span,
            "the result of an additive recalculation",
            "",
        ));
    }

    // The output read back as intrinsic angles (an extrinsic output is the
    // reversed intrinsic sequence, its gimbal zero on the intrinsic first angle).
    let (sequence, zero_first) = match p.output.kind {
        Kind::Intrinsic => (p.output, false),
        Kind::Extrinsic => (p.output.reversed(), true),
    };
    if !p.recalculate_only && options.form == Form::Cycle800 && sequence.is_proper_euler() {
        return Err(no_cycle800_form(p.output, span));
    }
    let angles = decompose(&mut code, &target, sequence, zero_first, options.precision);

    let precision = options.precision;
    let operand = |o: &Operand| match o {
        Operand::Known(v) => format(*v, precision),
        Operand::Runtime(text) => text.clone(),
    };
    let [x0, y0, z0, _, _, _, x1, y1, z1] = std::array::from_fn(|n| operand(&p.coordinates[n]));
    if p.recalculate_only {
        // _CYC600_2..4 hold the output angles in the output's own order.
        let ordered = if zero_first {
            [&angles[2], &angles[1], &angles[0]]
        } else {
            [&angles[0], &angles[1], &angles[2]]
        };
        code.blocks
            .push(format!("_CYC600_1=\"{}\" ; accessory", p.head));
        for (n, angle) in ordered.iter().enumerate() {
            code.blocks.push(format!(
                "_CYC600_{}={angle} ; output angle {}",
                n + 2,
                n + 1
            ));
        }
        code.blocks.push("_CYC600_5=1 ; calculated".to_string());
        code.blocks.push(format!(
            "_CYC600_6={} ; output sequence {}",
            p.output.code(),
            p.output
        ));
        return Ok(code.blocks);
    }
    match options.form {
        Form::Cycle800 => code.blocks.push(format!(
            "CYCLE800({},\"{}\",{},{},{x0},{y0},{z0},{},{},{},{x1},{y1},{z1},{})",
            u8::from(p.retract),
            p.head,
            u8::from(additive_on_control),
            sequence.code(),
            angles[0],
            angles[1],
            angles[2],
            if p.inverse { 1 } else { -1 }
        )),
        Form::Frames | Form::Traori => {
            if options.form == Form::Traori {
                code.blocks.push("TRAORI".to_string());
                code.blocks.push("ORIWKS".to_string());
            }
            let shift = if additive_on_control {
                "ATRANS"
            } else {
                "TRANS"
            };
            code.blocks.push(format!("{shift} X={x0} Y={y0} Z={z0}"));
            for (axis, angle) in sequence.axes.iter().zip(&angles) {
                code.blocks.push(format!("AROT {}={angle}", axis.letter()));
            }
            code.blocks.push(format!("ATRANS X={x1} Y={y1} Z={z1}"));
            if options.form == Form::Traori {
                code.blocks.push("G0 A3=0 B3=0 C3=1".to_string());
            }
        }
    }
    Ok(code.blocks)
}

/// Generates the decomposition of `m` in the intrinsic `sequence`; returns
/// the three angles as NC operands (variables, or numbers when known).
fn decompose(
    code: &mut Code,
    m: &PolyMatrix,
    sequence: rotation::Sequence,
    zero_first: bool,
    precision: usize,
) -> [String; 3] {
    // Fully known (only translations vary): the offline engine decides.
    if let Some(constant) = constant(m) {
        // Read back in the output sequence itself (the reversed intrinsic one
        // for an extrinsic output), then put the angles in intrinsic order.
        let output = if zero_first {
            sequence.reversed()
        } else {
            sequence
        };
        let d = rotation::decompose(
            output,
            &nalgebra::Rotation3::from_matrix_unchecked(constant),
        );
        let angles = if zero_first {
            [d.angles[2], d.angles[1], d.angles[0]]
        } else {
            d.angles
        };
        return angles.map(|a| format(a, precision));
    }
    let [first, second, _] = sequence.axes;
    let (i, j) = (first.index(), second.index());
    let k = 3 - i - j;
    let s = if (i + 1) % 3 == j { 1.0 } else { -1.0 };
    let proper = sequence.is_proper_euler();
    let mut el: Vec<Vec<Poly>> = vec![vec![Poly::default(); 3]; 3];
    for (r, row) in el.iter_mut().enumerate() {
        for (c, cell) in row.iter_mut().enumerate() {
            *cell = code.element(&m[r][c], r, c);
        }
    }
    let e = |r: usize, c: usize| el[r][c].clone();
    let letters = sequence.axes.map(|a| a.letter());
    let [a1_name, _, a3_name] = ["A1", "A2", "A3"].map(|base| code.names.get(base));

    // Middle angle, and |cos| (|sin| for proper Euler) of it as the gimbal test.
    let (condition_base, condition_what, pair_y, pair_x) = if proper {
        ("SB", "|sine| of the 2nd angle", e(j, i), e(k, i).scale(-s))
    } else {
        (
            "CB",
            "|cosine| of the 2nd angle",
            e(j, k).scale(-s),
            e(k, k),
        )
    };
    let (p, q) = if proper {
        (e(i, j), e(i, k))
    } else {
        (e(i, i), e(i, j))
    };
    let condition = code.assign(
        condition_base,
        format!("SQRT(POT({})+POT({}))", p.render(), q.render()),
        condition_what,
    );
    let second_angle = if proper {
        format!("ATAN2({condition},{})", e(i, i).render())
    } else {
        format!("ATAN2({},{condition})", e(i, k).scale(s).render())
    };
    let a2 = code.assign(
        "A2",
        second_angle,
        &format!("2nd angle, about {}", letters[1]),
    );

    // The third angle once the first is taken out, with the first angle's
    // (sin, cos) given as the (unnormalised) pair: atan2 ignores the scale.
    let row = |col: usize| pair_x.mul(&e(j, col)).add(&pair_y.scale(s).mul(&e(k, col)));
    let third = if proper {
        format!("ATAN2({},{})", row(k).scale(-s).render(), row(j).render())
    } else {
        format!("ATAN2({},{})", row(i).scale(s).render(), row(j).render())
    };
    code.blocks.push(format!(
        "IF {condition}<{} ; gimbal lock: the 1st and 3rd axes coincide",
        gimbal_literal()
    ));
    if zero_first {
        let third_alone = if proper {
            format!("ATAN2({},{})", e(j, k).scale(-s).render(), e(j, j).render())
        } else {
            format!("ATAN2({},{})", e(j, i).scale(s).render(), e(j, j).render())
        };
        code.blocks
            .push(format!("  {a1_name}=0 ; 1st angle set to 0"));
        code.blocks.push(format!(
            "  {a3_name}={third_alone} ; 3rd angle carries the whole rotation"
        ));
    } else {
        code.blocks.push(format!(
            "  {a1_name}=ATAN2({},{}) ; 1st angle carries the whole rotation",
            e(k, j).scale(s).render(),
            e(j, j).render()
        ));
        code.blocks
            .push(format!("  {a3_name}=0 ; 3rd angle set to 0"));
    }
    code.blocks.push("ELSE".to_string());
    code.blocks.push(format!(
        "  {a1_name}=ATAN2({},{}) ; 1st angle, about {}",
        pair_y.render(),
        pair_x.render(),
        letters[0]
    ));
    code.blocks.push(format!(
        "  {a3_name}={third} ; 3rd angle, about {}",
        letters[2]
    ));
    code.blocks.push("ENDIF".to_string());
    for name in [&a1_name, &a3_name] {
        code.blocks.push(format!(
            "{name}={name}+360*({name}<=-180) ; into (-180, 180]"
        ));
    }
    [a1_name, a2, a3_name]
}

/// The problem when the run-time variables would clash with the program's own.
pub fn collision(model: &Model, names: &Names) -> Option<Diagnostic> {
    let help = "rename the program's variables, or choose where the intermediate values go: local variables by default, R parameters with --runtime-r N";
    match names.r_range() {
        None => {
            let at = crate::syntax::lexer::find_ignoring_case(model.source, PREFIX.as_bytes())?;
            Some(
                registry::runtime_name_collision::RULE.at(Span::new(at, at + PREFIX.len()))
                    .message(format!("the program already uses names starting with {PREFIX}, which the run-time code needs"))
                    .label("already used")
                    .help(help),
            )
        }
        Some(range) => {
            let (n, span) = model.first_r_parameter(range.clone())?;
            Some(
                registry::runtime_name_collision::RULE
                    .at(span)
                    .message(format!(
                        "R{n} is used by the program, and the run-time code needs R{} to R{}",
                        range.start,
                        range.end - 1
                    ))
                    .label("already used")
                    .help(help),
            )
        }
    }
}

/// The threshold as NC text: `1EX-12`.
fn gimbal_literal() -> String {
    format!("1EX{}", GIMBAL_TOLERANCE.log10().round() as i32)
}

fn constant(m: &PolyMatrix) -> Option<Matrix3<f64>> {
    let mut out = Matrix3::zeros();
    for r in 0..3 {
        for c in 0..3 {
            out[(r, c)] = m[r][c].as_constant()?;
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polynomials_fold_constants_and_render_as_nc() {
        let s = Poly::var("SNP_S1".into());
        let half = Poly::constant(0.5);
        let p = s.mul(&half).add(&Poly::constant(-1.0)).add(&s.scale(-1.0));
        assert_eq!(p.render(), "-1-0.5*SNP_S1");
        assert_eq!(Poly::constant(0.0).render(), "0");
        assert_eq!(s.mul(&Poly::default()).as_constant(), Some(0.0));
    }

    #[test]
    fn names_are_local_variables_or_r_parameters() {
        let mut local = Names::new(None);
        assert_eq!(local.get("A1"), "SNP_A1");
        assert_eq!(local.get("A1"), "SNP_A1");
        let mut r = Names::new(Some(100));
        assert_eq!(
            (r.get("S1"), r.get("C1"), r.get("S1")),
            ("R100".into(), "R101".into(), "R100".into())
        );
        assert_eq!(r.r_range(), Some(100..102));
        assert!(r.locals().is_empty());
        assert_eq!(gimbal_literal(), "1EX-12");
    }

    #[test]
    fn the_prefix_and_the_r_parameters_are_found_in_any_case() {
        let model = Model::of(b"N10 snp_a1=1\nN20 r105=2\n");
        let clash = collision(&model, &Names::new(None)).expect("SNP_ in lower case");
        assert_eq!(clash.span, Span::new(4, 8));
        let mut r = Names::new(Some(100));
        for name in ["S1", "C1", "S2", "C2", "S3", "C3"] {
            r.get(name);
        }
        let clash = collision(&model, &r).expect("r105 in R100 to R105");
        assert_eq!(clash.span, Span::new(17, 21));
        assert!(collision(&Model::of(b"R99=1\n"), &r).is_none());
    }
}
