//! The dry run (`sinuprep run`): single-block times against their closed
//! forms, positions and limits against an independent sampler of the path
//! through the frames and the tool, and the command's outputs.

mod support;

use nalgebra::{Matrix3, Rotation3, Vector3};
use sinuprep::machine::MachineData;
use sinuprep::run::{run, BlockEnd, Options, Programs, Report, Setup, Side};
use sinuprep::semantic::{Model, Supplied};
use support::{assert_exit, run as command, scratch, stdout};

/// A three-axis mill's data as the control writes them: X1, Y1, Z1 named
/// X, Y, Z, 500 mm/s, 2.5 m/s², 40 m/s³; `extra` appended (limits, frames,
/// tools).
fn machine(extra: &str) -> String {
    let mut text = String::from(
        "%_N_INITIAL_INI\nN10000 $MN_AXCONF_MACHAX_NAME_TAB[0]=\"X1\"\n\
N10000 $MN_AXCONF_MACHAX_NAME_TAB[1]=\"Y1\"\nN10000 $MN_AXCONF_MACHAX_NAME_TAB[2]=\"Z1\"\n\
N10240 $MN_SCALING_SYSTEM_IS_METRIC=1\nN10600 $MN_FRAME_ANGLE_INPUT_MODE=1\nCHANDATA(1)\n\
N22550 $MC_TOOL_CHANGE_MODE=1\n",
    );
    for (k, name) in ["X", "Y", "Z"].iter().enumerate() {
        text.push_str(&format!(
            "N20070 $MC_AXCONF_MACHAX_USED[{k}]={}\nN20080 $MC_AXCONF_CHANAX_NAME_TAB[{k}]=\"{name}\"\n",
            k + 1
        ));
    }
    for axis in 1..=3 {
        text.push_str(&format!(
            "N30300 $MA_IS_ROT_AX[AX{axis}]=0\nN32000 $MA_MAX_AX_VELO[AX{axis}]=30000.\n\
N32300 $MA_MAX_AX_ACCEL[0,AX{axis}]=2.5\nN32431 $MA_MAX_AX_JERK[0,AX{axis}]=40.\n"
        ));
    }
    text.push_str(extra);
    text.push_str("M17\n");
    text
}

fn dry_run(machine_text: &str, program: &str) -> Report {
    dry_run_each(machine_text, program, |_| {})
}

/// [`dry_run`], each block's end handed to `each` as the run passes it.
fn dry_run_each(machine_text: &str, program: &str, each: impl FnMut(BlockEnd)) -> Report {
    dry_run_with(machine_text, program, &Options::default(), each)
}

/// [`dry_run`], ended after `block_limit` blocks.
fn dry_run_to(machine_text: &str, program: &str, block_limit: u64) -> Report {
    let options = Options {
        block_limit,
        ..Options::default()
    };
    dry_run_with(machine_text, program, &options, |_| {})
}

fn dry_run_with(
    machine_text: &str,
    program: &str,
    options: &Options,
    each: impl FnMut(BlockEnd),
) -> Report {
    let data = MachineData::read(machine_text.as_bytes());
    assert!(data.diagnostics.is_empty(), "{:?}", data.diagnostics);
    let records = sinuprep::semantic::machine::Machine::read(
        machine_text.as_bytes(),
        sinuprep::semantic::machine::Reading::default(),
    );
    let setup = Setup::of(&data).with_records(&records);
    let model = Model::of(program.as_bytes());
    let programs = Programs::alone(&model);
    run(&programs, &setup, &Supplied::default(), options, each)
}

/// Each block's line and machine positions at its end.
type Ends = Vec<(usize, Vec<Option<f64>>)>;

/// [`dry_run`], with each block's end.
fn dry_run_ends(machine_text: &str, program: &str) -> (Report, Ends) {
    let mut ends = Vec::new();
    let report = dry_run_each(machine_text, program, |end| {
        ends.push((end.line, end.mcs.to_vec()))
    });
    (report, ends)
}

fn assert_near(a: f64, b: f64, tolerance: f64, what: &str) {
    assert!((a - b).abs() <= tolerance, "{what}: {a} != {b}");
}

/// One axis, exact stop: the trapezoid of MD32000 and MD32300 (BRISK), the
/// jerk-limited profile of MD32431 (SOFT, ruckig 0.19.4's time), and a feed
/// under the axis's velocity.
#[test]
fn a_single_block_at_exact_stop_takes_the_closed_form_time() {
    let data = machine("");
    // 100 mm at 500 mm/s and 2500 mm/s²: 100/500 + 500/2500 = 0.4 s.
    let brisk = dry_run(&data, "G0 X0 Y0 Z0\nG60 G0 X100\nM30\n");
    assert_near(brisk.time_s, 0.4, 1e-12, "BRISK G0");
    assert_eq!(brisk.time_bounds_s, [brisk.time_s, brisk.time_s]);
    let soft = dry_run(&data, "G0 X0 Y0 Z0\nSOFT G60 G0 X100\nM30\n");
    assert_near(soft.time_s, 0.46735336851754117, 1e-12, "SOFT G0");
    // F6000: 100 mm/s, reached after 2 mm: 100/100 + 100/2500 s.
    let feed = dry_run(&data, "G0 X0 Y0 Z0\nG1 G9 X100 F6000\nM30\n");
    assert_near(feed.time_s, 1.04, 1e-12, "G1 G9");
    // Continuous path: at least the cruise, at most rest to rest.
    let path = dry_run(&data, "G0 X0 Y0 Z0\nG64 G1 X100 F6000\nM30\n");
    assert_near(path.time_bounds_s[0], 1.0, 1e-12, "G64 lower");
    assert_near(path.time_bounds_s[1], 1.04, 1e-12, "G64 upper");
    // A diagonal at G0 moves at √2 times the axes' own velocity.
    let diagonal = dry_run(&data, "G0 X0 Y0 Z0\nG60 G0 X300 Y300\nM30\n");
    let d = 300.0 * 2f64.sqrt();
    let (v, a) = (500.0 * 2f64.sqrt(), 2500.0 * 2f64.sqrt());
    assert_near(diagonal.time_s, d / v + v / a, 1e-12, "diagonal");
    // RTLIOF: each axis on its own, the block as long as the slowest.
    let single = dry_run(&data, "G0 X0 Y0 Z0\nRTLIOF G60 G0 X300 Y100\nM30\n");
    assert_near(
        single.time_s,
        300.0 / 500.0 + 500.0 / 2500.0,
        1e-12,
        "RTLIOF",
    );
    // A full circle of 10 mm at F60000: the centripetal acceleration caps
    // the path at sqrt(2500 · 10) mm/s, under the axes' 500 mm/s.
    let circle = dry_run(&data, "G0 X0 Y0 Z0\nG60 G2 X0 Y0 I10 F60000\nM30\n");
    let (d, v) = (std::f64::consts::TAU * 10.0, (2500.0f64 * 10.0).sqrt());
    assert_near(circle.time_s, d / v + v / 2500.0, 1e-9, "full circle");
    // A dwell counts its seconds.
    let dwell = dry_run(&data, "G4 F2.5\nM30\n");
    assert_near(dwell.time_s, 2.5, 1e-12, "G4");
}

/// A lathe's channel has no Y (MD20050 `[1]` = 0): its travel is not
/// reported, unless a program moves it.
#[test]
fn a_geometry_axis_the_channel_lacks_is_not_reported() {
    let lathe = "%_N_INITIAL_INI\nN10000 $MN_AXCONF_MACHAX_NAME_TAB[0]=\"X1\"\n\
N10000 $MN_AXCONF_MACHAX_NAME_TAB[1]=\"Z1\"\nCHANDATA(1)\n\
N20050 $MC_AXCONF_GEOAX_ASSIGN_TAB[0]=1\nN20050 $MC_AXCONF_GEOAX_ASSIGN_TAB[1]=0\n\
N20050 $MC_AXCONF_GEOAX_ASSIGN_TAB[2]=2\nN20060 $MC_AXCONF_GEOAX_NAME_TAB[0]=\"X\"\n\
N20060 $MC_AXCONF_GEOAX_NAME_TAB[1]=\"Y\"\nN20060 $MC_AXCONF_GEOAX_NAME_TAB[2]=\"Z\"\n\
N20070 $MC_AXCONF_MACHAX_USED[0]=1\nN20070 $MC_AXCONF_MACHAX_USED[1]=2\n\
N20080 $MC_AXCONF_CHANAX_NAME_TAB[0]=\"X\"\nN20080 $MC_AXCONF_CHANAX_NAME_TAB[1]=\"Z\"\nM17\n";
    let axes = |program: &str| -> Vec<String> {
        dry_run(lathe, program)
            .axes
            .into_iter()
            .map(|t| t.axis)
            .collect()
    };
    assert_eq!(axes("G0 X20 Z5\nG1 X10 Z-30 F200\nM30\n"), ["X1", "Z1"]);
    assert_eq!(axes("G0 X20 Y3 Z5\nM30\n"), ["X1", "Y", "Z1"]);
}

/// Under a rotated frame an axis programmed alone moves the machine's
/// geometry axes together: X20, then X30, after ROT Z90 is machine Y 20, then 30.
#[test]
fn under_a_rotation_one_axis_moves_the_machine_axes_together() {
    let report = dry_run(&machine(""), "G0 X0 Y0 Z0\nROT Z90\nG0 X20\nG0 X30\nM30\n");
    let (x, y) = (&report.axes[0], &report.axes[1]);
    assert!((y.max.expect("Y") - 30.0).abs() < 1e-9, "{report:?}");
    assert!(
        x.max.expect("X").abs() < 1e-9 && x.min.expect("X").abs() < 1e-9,
        "{report:?}"
    );
}

/// Polar coordinates (Programming Manual Fundamentals, "Travel commands
/// with polar coordinates"): a pole by G111 (in the work's coordinates) and
/// G112 (from the last pole), moves by AP (from the plane's horizontal
/// axis, counter-clockwise, AC/IC) and RP (kept until a new one), an arc
/// about the pole, a new plane measuring from its own horizontal axis.
#[test]
fn polar_coordinates_move_about_the_pole() {
    let program = "G17 G0 X10 Y30 Z10\n\
                   G111 X10 Y20\n\
                   G1 AP=0 RP=30 F1000\n\
                   AP=90\n\
                   AP=IC(90)\n\
                   G112 X5 Y0\n\
                   AP=AC(180) RP=5\n\
                   G3 AP=0\n\
                   G110 X-5 Y5\n\
                   G1 AP=270\n\
                   G110 AP=45 RP=10\n\
                   G1 G18 AP=0 RP=1\n\
                   G91 AP=45\n\
                   M30\n";
    let mut ends: Vec<(usize, [f64; 3])> = Vec::new();
    let report = dry_run_each(&machine(""), program, |end| {
        let at = |k: usize| end.mcs[k].expect("known");
        ends.push((end.line, [at(0), at(1), at(2)]));
    });
    let at = |line: usize| {
        ends.iter()
            .rev()
            .find(|(l, _)| *l == line)
            .map(|(_, p)| *p)
            .expect("the block's end")
    };
    let near = |a: [f64; 3], b: [f64; 3], what: &str| {
        for k in 0..3 {
            assert_near(a[k], b[k], 1e-9, what);
        }
    };
    near(at(3), [40.0, 20.0, 10.0], "AP=0 RP=30 about (10, 20)");
    near(at(4), [10.0, 50.0, 10.0], "AP=90, the radius kept");
    near(at(5), [-20.0, 20.0, 10.0], "AP=IC(90) from 90");
    near(at(7), [10.0, 20.0, 10.0], "AP=AC(180) RP=5 about (15, 20)");
    near(at(8), [20.0, 20.0, 10.0], "G3 to AP=0 about the pole");
    // The arc from 180 degrees counter-clockwise to 0 passes 270: Y 15.
    assert_near(
        report.axes[1].min.expect("Y"),
        15.0,
        1e-9,
        "the arc's lowest point",
    );
    // G110: from the last position (20, 20), a new pole (15, 25), the
    // angle forgotten, the radius kept.
    near(at(10), [15.0, 20.0, 10.0], "G110 X-5 Y5, then AP=270");
    // G18: the horizontal axis is Z, the vertical X; the pole's Z is the
    // position's where G110 set it.
    near(at(12), [15.0, 20.0, 11.0], "G18 AP=0 RP=1");
    // AP under G91 without AC or IC, and a pole by G110 with AP and RP,
    // are named, not guessed.
    let unknown = format!("{:?}", report.unknown);
    assert!(unknown.contains("AP= under G91"), "{unknown}");
    assert!(
        unknown.contains("a pole by G110 with AP= and RP="),
        "{unknown}"
    );
    assert!(!unknown.contains("polar coordinates"), "{unknown}");
}

/// An arc by its end and opening angle (`AR=`: the centre on the side its
/// direction and angle give, past 180 degrees the long way) and a helix's
/// full turns more (`TURN=`: their length in its time).
#[test]
fn an_arc_by_its_opening_angle_and_a_helix_by_its_turns() {
    let travel = |program: &str| {
        let report = dry_run(&machine(""), program);
        let (x, y) = (&report.axes[0], &report.axes[1]);
        let pair = |a: Option<f64>, b: Option<f64>| [a.expect("min"), b.expect("max")];
        (pair(x.min, x.max), pair(y.min, y.max), report)
    };
    let near = |a: [f64; 2], b: [f64; 2], what: &str| {
        assert_near(a[0], b[0], 1e-9, what);
        assert_near(a[1], b[1], 1e-9, what);
    };
    // A half turn counter-clockwise from (0, 0) to (20, 0): about (10, 0), down to Y -10.
    let (x, y, _) = travel("G17 G0 X0 Y0 Z0\nG3 X20 Y0 AR=180 F600\nM30\n");
    near(x, [0.0, 20.0], "AR=180 X");
    near(y, [-10.0, 0.0], "AR=180 Y");
    // Three quarters clockwise from (0, 0) to (10, 10): radius 10 about (0, 10).
    let (x, y, _) = travel("G17 G0 X0 Y0 Z0\nG2 X10 Y10 AR=270 F600\nM30\n");
    near(x, [-10.0, 10.0], "AR=270 X");
    near(y, [0.0, 20.0], "AR=270 Y");
    // A quarter the short way is the same arc as CR=+radius.
    let (x, y, _) = travel("G17 G0 X0 Y0 Z0\nG2 X10 Y10 AR=90 F600\nM30\n");
    let (cx, cy, _) = travel("G17 G0 X0 Y0 Z0\nG2 X10 Y10 CR=10 F600\nM30\n");
    near(x, cx, "AR=90 as CR=10, X");
    near(y, cy, "AR=90 as CR=10, Y");
    // One full turn down 6 mm, and the same with two turns more: each
    // takes the closed form d/v + v/a at the feed (10 mm/s), `a` MD32300
    // (2,500 mm/s²) over the geometry axes' largest share of the path
    // (the circle's: its length in the plane over the helix's).
    let helix = |turns: &str| {
        let program = format!("G17 G0 X10 Y0 Z0\nG3 X10 Y0 Z-6 I-10 J0 {turns} F600\nM30\n");
        let (x, _, report) = travel(&program);
        near(x, [-10.0, 10.0], "the helix's X");
        report.time_s
    };
    let in_plane = |turns: f64| 10.0 * turns * std::f64::consts::TAU;
    let time = |turns: f64| {
        let length = in_plane(turns).hypot(6.0);
        length / 10.0 + 10.0 / (2500.0 / (in_plane(turns) / length))
    };
    let extra = helix("TURN=2") - helix("");
    assert_near(extra, time(3.0) - time(1.0), 1e-9, "two turns more");
    // By its centre and opening: a quarter counter-clockwise from (0, 0)
    // about (10, 0) ends at (10, -10); clockwise, at (10, 10).
    let (x, y, _) = travel("G17 G0 X0 Y0 Z0\nG3 I10 J0 AR=90 F600\nM30\n");
    near(x, [0.0, 10.0], "I J AR=90 counter-clockwise, X");
    near(y, [-10.0, 0.0], "I J AR=90 counter-clockwise, Y");
    let (x, y, _) = travel("G17 G0 X0 Y0 Z0\nG2 I=AC(10) J0 AR=270 F600\nM30\n");
    near(x, [0.0, 20.0], "I=AC J AR=270 clockwise, X");
    near(y, [-10.0, 10.0], "I=AC J AR=270 clockwise, Y");
    // G18: the plane's horizontal axis is Z, its vertical X.
    let (x, _, report) = travel("G18 G0 X0 Y0 Z0\nG3 K10 I0 AR=90 F600\nM30\n");
    near(x, [-10.0, 0.0], "G18 K I AR=90, X");
    let z = &report.axes[2];
    near(
        [z.min.expect("Z"), z.max.expect("Z")],
        [0.0, 10.0],
        "G18 K I AR=90, Z",
    );
}

/// DYNNORM..DYNFINISH choose the dynamic response group whose MD32300 a
/// block takes, and CYCLE832 chooses one by its machining type as the
/// standard cycle does (said among the assumptions): a 100 mm move at
/// 100 mm/s, exact stop, takes d/v + v/a of the group chosen.
#[test]
fn the_dynamic_response_follows_the_program() {
    let machine =
        machine("N32300 $MA_MAX_AX_ACCEL[2,AX1]=1.\nN32300 $MA_MAX_AX_ACCEL[4,AX1]=0.5\n");
    let program = "G0 X0 Y0 Z0\nG1 X100 F6000\nDYNFINISH\nG1 X0\n\
                   CYCLE832(0.01, 3, 1)\nG1 X100\nCYCLE832(0.01, 1001, 1)\nG1 X0\n\
                   CYCLE832()\nG1 X100\nM30\n";
    let mut times: Vec<(usize, f64)> = Vec::new();
    let report = dry_run_each(&machine, program, |end| times.push((end.line, end.t_s)));
    let took = |line: usize| {
        let at = times
            .iter()
            .position(|(l, _)| *l == line)
            .expect("the block");
        times[at].1 - times[at - 1].1
    };
    let closed = |a: f64| 100.0 / 100.0 + 100.0 / a;
    assert_near(took(2), closed(2500.0), 1e-9, "DYNNORM, MD32300[0]");
    assert_near(took(4), closed(500.0), 1e-9, "DYNFINISH, MD32300[4]");
    assert_near(
        took(6),
        closed(1000.0),
        1e-9,
        "CYCLE832 roughing: DYNROUGH, MD32300[2]",
    );
    assert_near(
        took(8),
        closed(500.0),
        1e-9,
        "CYCLE832 finishing (units digit 1): DYNFINISH",
    );
    assert_near(took(10), closed(2500.0), 1e-9, "CYCLE832(): DYNNORM");
    assert!(
        report.assumptions.iter().any(|a| a.contains("CUST_832")),
        "{:?}",
        report.assumptions
    );
    let unknown = format!("{:?}", report.unknown);
    assert!(!unknown.contains("DYNFINISH"), "{unknown}");
}

/// SCALE and MIRROR replace the programmable frame as TRANS and ROT do;
/// ASCALE and AMIRROR add to it: X5 under TRANS X10 then ASCALE X2 is 20,
/// under SCALE X2 alone 10, mirrored -10.
#[test]
fn scale_and_mirror_act_as_the_control_composes_them() {
    // The machine X's travel: from 0 to where X5 takes it.
    let x = |frames: &str| {
        let program = format!("G0 X0 Y0 Z0\n{frames}\nG0 X5\nM30\n");
        let report = dry_run(&machine(""), &program);
        assert!(
            report.unknown.iter().all(|u| u.line != 2 && u.line != 3),
            "{:?}",
            report.unknown
        );
        (report.axes[0].min, report.axes[0].max)
    };
    assert_eq!(x("TRANS X10\nASCALE X2"), (Some(0.0), Some(20.0)));
    assert_eq!(x("TRANS X10\nSCALE X2"), (Some(0.0), Some(10.0)));
    assert_eq!(x("SCALE X2\nAMIRROR X0"), (Some(-10.0), Some(0.0)));
}

/// A small generator of numbers (the tests need no crate for it).
struct Numbers(u64);

impl Numbers {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A value in `low..high`, written with four decimals as a program
    /// would be, and read back as the control reads it.
    fn between(&mut self, low: f64, high: f64) -> f64 {
        let value = low + (high - low) * self.next();
        format!("{value:.4}").parse().expect("number")
    }
}

/// A generated program and the machine positions an independent sampler
/// finds along it: every point of every block, through the settable frame,
/// the programmable frame and the tool.
struct Generated {
    program: String,
    frames: String,
    extremes: [[f64; 2]; 3],
}

fn generate(seed: u64) -> Generated {
    let mut numbers = Numbers(seed);
    // G54: a shift and a turn about Z; TRANS and AROT in the program.
    let shift = [
        numbers.between(-300.0, 300.0),
        numbers.between(-300.0, 300.0),
        numbers.between(-300.0, 0.0),
    ];
    let turn = numbers.between(-45.0, 45.0);
    let trans = [
        numbers.between(-20.0, 20.0),
        numbers.between(-20.0, 20.0),
        numbers.between(-5.0, 5.0),
    ];
    let arot = [
        numbers.between(-10.0, 10.0),
        0.0,
        numbers.between(-30.0, 30.0),
    ];
    let length = numbers.between(50.0, 150.0);
    let frames = format!(
        "$P_UIFR[1,X,TR]={}\n$P_UIFR[1,Y,TR]={}\n$P_UIFR[1,Z,TR]={}\n$P_UIFR[1,Z,RT]={turn}\n\
$TC_DP1[1,1]=120\n$TC_DP3[1,1]={length}\n",
        shift[0], shift[1], shift[2]
    );
    let settable = Rotation3::from_axis_angle(&Vector3::z_axis(), turn.to_radians());
    // ASCALE by one factor (a circle stays a circle), AMIRROR of X half the time.
    let scale = numbers.between(0.5, 2.0);
    let mirror = numbers.next() < 0.5;
    let programmable = (Rotation3::from_axis_angle(&Vector3::z_axis(), arot[2].to_radians())
        * Rotation3::from_axis_angle(&Vector3::x_axis(), arot[0].to_radians()))
    .into_inner()
        * Matrix3::from_diagonal(&Vector3::new(
            if mirror { -scale } else { scale },
            scale,
            scale,
        ));
    let mut program = format!(
        "G54 G17 G90 T1 M6 D1\nTRANS X{} Y{} Z{}\nAROT X{} Z{}\nASCALE X{scale} Y{scale} Z{scale}\n{}F2000\n",
        trans[0],
        trans[1],
        trans[2],
        arot[0],
        arot[2],
        if mirror { "AMIRROR X0\n" } else { "" }
    );
    let mut extremes = [[f64::MAX, f64::MIN]; 3];
    let mut sample = |p: Vector3<f64>, plane: usize| {
        let inner = programmable * p + Vector3::new(trans[0], trans[1], trans[2]);
        let mut machine = settable * inner + Vector3::new(shift[0], shift[1], shift[2]);
        machine[[2, 1, 0][plane]] += length;
        for k in 0..3 {
            extremes[k][0] = extremes[k][0].min(machine[k]);
            extremes[k][1] = extremes[k][1].max(machine[k]);
        }
    };
    let mut at = Vector3::new(0.0, 0.0, 10.0);
    program.push_str("G0 X0 Y0 Z10\n");
    sample(at, 0);
    for _ in 0..12 {
        if numbers.next() < 0.4 {
            let to = Vector3::new(
                numbers.between(-60.0, 60.0),
                numbers.between(-60.0, 60.0),
                numbers.between(-30.0, 10.0),
            );
            program.push_str(&format!("G1 X{} Y{} Z{}\n", to.x, to.y, to.z));
            // A straight line reaches its extremes at its ends.
            sample(to, 0);
            at = to;
            continue;
        }
        // An arc (a helix half the time) in a plane drawn at random.
        let plane = (numbers.next() * 3.0) as usize % 3;
        let [p, q, a] = [[0, 1, 2], [2, 0, 1], [1, 2, 0]][plane];
        let radius = numbers.between(2.0, 40.0);
        let from = numbers.next() * std::f64::consts::TAU;
        let mut centre = at;
        centre[p] = at[p] - radius * from.cos();
        centre[q] = at[q] - radius * from.sin();
        let counterclockwise = numbers.next() < 0.5;
        let sweep = numbers.between(0.1, 6.2);
        let to_angle = if counterclockwise {
            from + sweep
        } else {
            from - sweep
        };
        let rise = if numbers.next() < 0.5 {
            0.0
        } else {
            numbers.between(-5.0, 5.0)
        };
        let mut end = at;
        end[p] = centre[p] + radius * to_angle.cos();
        end[q] = centre[q] + radius * to_angle.sin();
        end[a] = at[a] + rise;
        // Written with four decimals, as the program holds it: the centre
        // is the start plus I, J, K so written, the end as written.
        let letters = ["X", "Y", "Z"];
        let offsets = ["I", "J", "K"];
        let write = |v: f64| format!("{v:.4}");
        let end_written = end.map(|v| write(v).parse::<f64>().expect("number"));
        let offset_p = write(centre[p] - at[p]);
        let offset_q = write(centre[q] - at[q]);
        let centre_read = {
            let mut c = at;
            c[p] = at[p] + offset_p.parse::<f64>().expect("number");
            c[q] = at[q] + offset_q.parse::<f64>().expect("number");
            c
        };
        program.push_str(&format!(
            "G{} G{} X{} Y{} Z{} {}{offset_p} {}{offset_q}\n",
            [17, 18, 19][plane],
            if counterclockwise { 3 } else { 2 },
            write(end.x),
            write(end.y),
            write(end.z),
            offsets[p],
            offsets[q],
        ));
        let _ = letters;
        // The sampler: the angle from start to end the way the arc turns.
        let start_angle = (at[q] - centre_read[q]).atan2(at[p] - centre_read[p]);
        let end_angle = (end_written[q] - centre_read[q]).atan2(end_written[p] - centre_read[p]);
        let mut swept = if counterclockwise {
            (end_angle - start_angle).rem_euclid(std::f64::consts::TAU)
        } else {
            (start_angle - end_angle).rem_euclid(std::f64::consts::TAU)
        };
        if swept < 1e-9 {
            swept = std::f64::consts::TAU;
        }
        // The end as written lies off the circle by the rounding: the
        // control closes the difference along the arc, the radius going
        // from the start's to the end's.
        let r = (at[p] - centre_read[p]).hypot(at[q] - centre_read[q]);
        let r_end = (end_written[p] - centre_read[p]).hypot(end_written[q] - centre_read[q]);
        let steps = 20_000;
        for i in 0..=steps {
            let t = swept * i as f64 / steps as f64;
            let angle = if counterclockwise {
                start_angle + t
            } else {
                start_angle - t
            };
            let mut point = at;
            let radius = r + (r_end - r) * t / swept;
            point[p] = centre_read[p] + radius * angle.cos();
            point[q] = centre_read[q] + radius * angle.sin();
            point[a] = at[a] + (end_written[a] - at[a]) * t / swept;
            sample(point, plane);
        }
        sample(end_written, plane);
        program.push_str("G17\n");
        at = end_written;
    }
    program.push_str("M30\n");
    Generated {
        program,
        frames,
        extremes,
    }
}

/// Generated programs (frames with a shift, turns, a scale and a mirror, a
/// tool, lines, arcs and helices in the three planes): the run's travel per axis is the sampler's, and a limit placed
/// just inside the true extreme is a violation where one just outside is
/// none, on every side of every axis.
#[test]
fn positions_and_limits_agree_with_a_sampler_of_the_path() {
    for seed in 1..=40u64 {
        let generated = generate(seed);
        let report = dry_run(&machine(&generated.frames), &generated.program);
        // Only the first move's start is unknown (the program's start).
        let unknown: Vec<_> = report
            .unknown
            .iter()
            .filter(|u| {
                !u.why
                    .starts_with("where the axes were before this block is unknown")
            })
            .collect();
        assert!(
            unknown.is_empty(),
            "seed {seed}: {unknown:?}\n{}",
            generated.program
        );
        for k in 0..3 {
            let travel = &report.axes[k];
            let [low, high] = generated.extremes[k];
            // The run's extremes are the sampler's, within what the
            // rounding of the end points to four decimals moves the arcs
            // (the run takes the start's radius throughout).
            let (min, max) = (travel.min.expect("min"), travel.max.expect("max"));
            assert!(
                (min - low).abs() < 5e-4 && (max - high).abs() < 5e-4,
                "seed {seed}, axis {k}: run {min}..{max}, sampler {low}..{high}\n{}",
                generated.program
            );
            for (side, limit, inside) in [
                (Side::Plus, high - 1e-3, true),
                (Side::Plus, high + 1e-3, false),
                (Side::Minus, low + 1e-3, true),
                (Side::Minus, low - 1e-3, false),
            ] {
                let datum = match side {
                    Side::Plus => "N36110 $MA_POS_LIMIT_PLUS",
                    Side::Minus => "N36100 $MA_POS_LIMIT_MINUS",
                };
                let limited = format!("{}{datum}[AX{}]={limit}\n", generated.frames, k + 1);
                let report = dry_run(&machine(&limited), &generated.program);
                let found = report
                    .violations
                    .iter()
                    .any(|v| v.side == side && v.axis == format!("{}1", ["X", "Y", "Z"][k]));
                assert_eq!(
                    found, inside,
                    "seed {seed}, axis {k}, {side:?} limit {limit} (extreme {low}..{high}): {:?}\n{}",
                    report.violations, generated.program
                );
            }
        }
    }
}

/// What cannot be known offline is named with its block, and the run goes
/// on: a measured value in a condition, a subprogram not followed, a
/// frame the machine lacks.
#[test]
fn what_is_unknown_offline_is_named_with_its_block() {
    let report = dry_run(
        &machine(""),
        "G0 X0 Y0 Z0\nIF $AA_IM[X]>5\nG0 X500\nENDIF\nL105\nG55\nG1 X=R7 F100\nM30\n",
    );
    let lines: Vec<(usize, &str)> = report
        .unknown
        .iter()
        .map(|u| (u.line, u.why.as_str()))
        .collect();
    assert!(
        lines
            .iter()
            .any(|(l, why)| *l == 2 && why.contains("$AA_IM[X]") && why.contains("taken as false")),
        "{lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|(l, why)| *l == 5 && why.contains("`L105` is not followed")),
        "{lines:?}"
    );
    assert!(
        lines.iter().any(|(l, why)| *l == 6 && why.contains("G55")),
        "{lines:?}"
    );
    assert!(
        lines.iter().any(|(l, why)| *l == 7 && why.contains("R7")),
        "{lines:?}"
    );
    // The IF's branch was not taken: X never reached 500.
    assert_eq!(report.axes[0].max, Some(0.0));
    // A base frame that moves something is named, not applied.
    let report = dry_run(&machine("$P_CHBFR[0,X,TR]=5\n"), "G0 X0 Y0 Z0\nM30\n");
    assert!(
        report
            .unknown
            .iter()
            .any(|u| u.line == 0 && u.why.contains("base frames CHBFR0")),
        "{:?}",
        report.unknown
    );
    assert_eq!(report.axes[0].max, Some(0.0));
}

/// A run-in program: a pass over the table that jumps back to its start.
/// `passes`: `None` for the endless original, `Some(n)` for the same pass
/// written out n times and ended.
fn run_in(passes: Option<usize>) -> String {
    let pass = "G1 X100 F6000\nG1 Y50\nG2 X50 Y100 CR=50\nG0 Z5\nG0 X0 Y0 Z0\n";
    match passes {
        None => format!("G0 X0 Y0 Z0\nSTART:\n{pass}GOTOB START\n"),
        Some(n) => format!("G0 X0 Y0 Z0\n{}M30\n", pass.repeat(n)),
    }
}

/// A program that comes back to a state it was in runs until it is
/// stopped: the run ends there, says where and how long a pass takes, and
/// has found all it ever will (the travel and the violations of the same
/// passes written out and ended).
#[test]
fn a_program_that_comes_back_to_a_state_repeats_it_for_ever() {
    let data = machine("N36110 $MA_POS_LIMIT_PLUS[AX3]=2\n");
    let endless = dry_run(&data, &run_in(None));
    let found = endless.endless.as_ref().expect("endless");
    assert_eq!((found.line, found.from_line), (2, 8), "{found:?}");
    assert!(!found.rests_on_unknown, "{:?}", endless.unknown);
    // One pass: its 7 blocks (the label, five moves, the jump), and the time
    // of one more pass written out.
    assert_eq!(found.pass_blocks, 7);
    let (one, two) = (
        dry_run(&data, &run_in(Some(1))),
        dry_run(&data, &run_in(Some(2))),
    );
    assert_near(found.pass_s, two.time_s - one.time_s, 1e-9, "a pass");
    assert!(found.pass_s > 0.0);
    let written_out = dry_run(&data, &run_in(Some(3)));
    assert_eq!(endless.axes, written_out.axes);
    let places = |r: &Report| -> Vec<(String, Side, f64)> {
        let mut v: Vec<_> = r
            .violations
            .iter()
            .map(|v| (v.axis.clone(), v.side, v.value))
            .collect();
        v.dedup();
        v
    };
    assert!(!places(&endless).is_empty());
    assert_eq!(places(&endless), places(&written_out));
    // Every way back: LOOP, WHILE 1, a section that calls itself... each
    // with the same pass.
    for program in [
        "G0 X0 Y0 Z0\nLOOP\nG1 X10 F600\nG0 X0\nENDLOOP\n",
        "G0 X0 Y0 Z0\nWHILE 1\nG1 X10 F600\nG0 X0\nENDWHILE\nM30\n",
        "G0 X0 Y0 Z0\nN10 G1 X10 F600\nG0 X0\nGOTOB N10\n",
        "G0 X0 Y0 Z0\nSTART: G1 X10 F600\nG0 X0\nGOTO START\n",
    ] {
        let report = dry_run(&data, program);
        let found = report
            .endless
            .as_ref()
            .unwrap_or_else(|| panic!("{program}"));
        // G1 at 10 mm/s: 10/10 + 10/2500 s; G0 over 10 mm, too short to
        // reach 500 mm/s: 2 sqrt(10/2500) s.
        let pass = 1.0 + 10.0 / 2500.0 + 2.0 * (10.0f64 / 2500.0).sqrt();
        assert_near(found.pass_s, pass, 1e-9, program);
    }
    // A counter that wraps: the state comes back after k passes, not one.
    for k in 1..=12u32 {
        let program = format!(
            "G0 X0 Y0 Z0\nR1=0\nSTART:\nG0 X=R1*10\nR1=R1+1\nIF R1=={k} GOTOF WRAP\nGOTOB START\n\
WRAP:\nR1=0\nGOTOB START\n"
        );
        let report = dry_run(&data, &program);
        let found = report.endless.as_ref().expect("endless");
        // Each pass 5 blocks (START to GOTOB), the last 7 (to WRAP's GOTOB).
        assert_eq!(found.pass_blocks, 5 * u64::from(k) + 2, "k = {k}");
        assert_eq!(report.axes[0].max, Some(f64::from(k - 1) * 10.0), "k = {k}");
    }
    // A warm-up program that counts its passes: the counter, which nothing
    // else reads, is left aside and named.
    let counted = dry_run(
        &data,
        "DEF INT _PASS\nG0 X0 Y0 Z0\nLOOP\n_PASS=_PASS+1\nMSG(\"pass \"<<_PASS)\nG1 X10 F600\nG0 X0\nENDLOOP\n",
    );
    let found = counted.endless.expect("endless");
    assert_eq!(found.counting, ["_PASS"]);
    assert_eq!(found.pass_blocks, 5);
    // -0 is not 0: ATAN2(-0, -1) is -180, ATAN2(0, -1) 180. The second pass
    // comes back with R1 = -0 and leaves.
    let signed = dry_run(
        &data,
        "G0 X0 Y0 Z0\nR1=0\nGOTOF BACK\nSTART: IF ATAN2(R1,-1)<0 GOTOF OUT\nR1=-R1\nBACK: GOTOB START\nOUT: G0 X5\nM30\n",
    );
    assert_eq!(signed.endless, None);
    assert_eq!(signed.axes[0].max, Some(5.0));
    // What the run does not model stays with the verdict: a synchronized
    // action that may set R1 in any block, a procedure of the control
    // (EXECSTRING) not run offline.
    for program in [
        "G0 X0 Y0 Z0\nR1=0\nID=1 WHEN $AC_TIMER[1]>10 DO $R1=1\nSTART: G0 X10\nSTOPRE\nIF R1==0 GOTOB START\nM30\n",
        "G0 X0 Y0 Z0\nR2=0\nSTART: G0 X10\nEXECSTRING(\"R2=R2+1\")\nIF R2<5 GOTOB START\nM30\n",
    ] {
        let report = dry_run(&data, program);
        let found = report.endless.expect(program);
        assert!(found.rests_on_unknown, "{program}");
    }
    // What the run could not know and took for something is said with it.
    let guessed = dry_run(
        &data,
        "G0 X0 Y0 Z0\nLOOP\nG0 X10\nIF $AA_IM[X]>1000 GOTOF OUT\nENDLOOP\nOUT:\nM30\n",
    );
    assert!(guessed.endless.expect("endless").rests_on_unknown);
}

/// A loop that ends, or that never comes back to a state (an axis that
/// goes on, a counter that counts on), is never taken for endless.
#[test]
fn a_loop_that_ends_or_goes_on_is_not_taken_for_endless() {
    let data = machine("");
    for n in [1u32, 2, 3, 7, 64, 65, 1000] {
        // The positions repeat, the counter does not: n passes, then M30.
        let counted = dry_run(
            &data,
            &format!(
                "G0 X0 Y0 Z0\nR1=0\nSTART:\nG0 X10\nG0 X0\nR1=R1+1\nIF R1<{n} GOTOB START\nM30\n"
            ),
        );
        assert_eq!(counted.endless, None, "n = {n}");
        assert_eq!(counted.blocks, 3 + 5 * u64::from(n), "n = {n}");
        // A subprogram called n times by a section repeated, every level's
        // state the same but for the repetitions still to come.
        let repeated = dry_run(
            &data,
            &format!("G0 X0 Y0 Z0\nSTART:\nG0 X10\nG0 X0\nREPEAT START P={n}\nM30\n"),
        );
        assert_eq!(repeated.endless, None, "n = {n}");
    }
    // An axis that moves on at each pass: never the same state; the run
    // goes on to its block limit, and tells the travel it passes.
    let report = dry_run_to(
        &data,
        "G0 X0 Y0 Z0\nSTART:\nG91 G0 X0.1\nG90\nGOTOB START\n",
        3000,
    );
    assert_eq!(report.endless, None);
    assert_eq!(report.blocks, 3000);
    assert!(
        report.axes[0].max.is_some_and(|x| x > 74.0),
        "{:?}",
        report.axes[0]
    );
    // A counter read where the trees do not show it (a REPEAT's count) is
    // no counter: every pass is longer than the one before.
    let repeated =
        "G0 X0 Y0 Z0\nR5=0\nLOOP\nR5=R5+1\nSEC: G0 X1\nG0 X0\nREPEAT SEC P=R5\nENDLOOP\n";
    assert_eq!(dry_run_to(&data, repeated, 3000).endless, None);
    // R1 feeds an arc's radius (an address, not a variable), R2 a square
    // root that fails at the 11th pass: neither is a counter.
    for program in [
        "G17 G90 G0 X0 Y0 Z0 F1000\nR1=20\nLOOP\nR1=R1-1\nG2 X10 Y0 CR=R1\nG2 X0 Y0 CR=R1\nENDLOOP\n",
        "G0 X0 Y0 Z0\nR1=0\nLOOP\nR1=R1+1\nR2=SQRT(10-R1)\nG0 X10\nG0 X0\nENDLOOP\n",
    ] {
        let report = dry_run_to(&data, program, 3000);
        assert!(
            report.endless.as_ref().is_none_or(|e| e.rests_on_unknown),
            "{program}: {:?}",
            report.endless
        );
    }
}

/// A subprogram's VAR parameter is not given back offline: a loop that
/// waits for it is endless only as run here, and says so. GUD variables are
/// the channel's (what a level writes, the others read), and RET ends a
/// subprogram: loops that end on them end.
#[test]
fn what_a_subprogram_gives_back_decides_the_verdict() {
    let dir = scratch("run_endless_var");
    let files = [
        ("MACHINE.INI", machine("")),
        ("VAR.MPF", "DEF INT _K=0\nG0 X0 Y0 Z0\nSTART: COUNT(_K)\nG0 X10\nG0 X0\nIF _K<5 GOTOB START\nM30\n".into()),
        ("COUNT.SPF", "PROC COUNT(VAR INT _N)\n_N=_N+1\nM17\n".into()),
        ("GUD.MPF", "G0 X0 Y0 Z0\nSTART: BUMP\nG0 X10\nG0 X0\nIF _GUD_N<5 GOTOB START\nG0 Y=_GUD_N\nM30\n".into()),
        ("BUMP.SPF", "_GUD_N=_GUD_N+1\nM17\n".into()),
        ("SET.MPF", "G0 X0 Y0 Z0\n_GUD_N=1\nWAIT\nG0 Y7\nM30\n".into()),
        ("WAIT.SPF", "START: G0 X10\nG0 X0\nIF _GUD_N==0 GOTOB START\nM17\n".into()),
        ("RET.MPF", "G0 X0 Y0 Z0\nBACK\nG0 Y7\nM30\n".into()),
        ("BACK.SPF", "START: G0 X10\nRET\nG0 X0\nGOTOB START\n".into()),
    ];
    for (name, text) in &files {
        std::fs::write(dir.join(name), text).expect("write");
    }
    // The GUD variable's value at the start given, as the control holds it.
    let run = |main: &str| -> serde_json::Value {
        let json = command(
            &[
                "run",
                "--machine",
                dir.join("MACHINE.INI").to_str().expect("utf-8"),
                "--format",
                "json",
                "--set",
                "_GUD_N=0",
                dir.join(main).to_str().expect("utf-8"),
            ],
            b"",
        );
        serde_json::from_str(&stdout(&json)).expect("JSON")
    };
    let var = run("VAR.MPF");
    assert_eq!(var["endless"]["rests_on_unknown"], true, "{var}");
    let gud = run("GUD.MPF");
    assert_eq!(gud["endless"], serde_json::Value::Null, "{gud}");
    assert_eq!(gud["axes"]["Y1"]["max"], 5.0, "{gud}");
    for main in ["SET.MPF", "RET.MPF"] {
        let read = run(main);
        assert_eq!(read["endless"], serde_json::Value::Null, "{main}: {read}");
        assert_eq!(read["axes"]["Y1"]["max"], 7.0, "{main}: {read}");
    }
}

/// Calls nested past the control's program levels stop the run where the
/// control stops with its alarm: a subprogram calling itself three times,
/// an L-number repeated 9999 times and calling itself, a REPEAT of a
/// section holding it, each end at the limit within a few hundred blocks
/// (going on past it ran each level's calls again: tens of millions).
#[test]
fn calls_nested_past_the_program_levels_stop_the_run() {
    let dir = scratch("run_nested_past_levels");
    let files = [
        ("MACHINE.INI", machine("")),
        ("SELF.MPF", "G0 X0 Y0 Z0\nSUBX\nG0 Y7\nM30\n".into()),
        (
            "SUBX.SPF",
            "PROC SUBX\nG1 X1 F10\nSUBX\nSUBX\nSUBX\nM17\n".into(),
        ),
        ("NUMBER.MPF", "G0 X0 Y0 Z0\nL10\nG0 Y7\nM30\n".into()),
        ("L10.SPF", "G0 X1\nL10 P9999\nM17\n".into()),
        (
            "SECTION.MPF",
            "G0 X0 Y0 Z0\nSTART: G0 X1\nREPEAT START FIN P=3\nFIN: G0 X2\nG0 Y7\nM30\n".into(),
        ),
    ];
    for (name, text) in &files {
        std::fs::write(dir.join(name), text).expect("write");
    }
    for main in ["SELF.MPF", "NUMBER.MPF", "SECTION.MPF"] {
        let report = run_program_with_blocks(&dir, main);
        let blocks = report["blocks"].as_array().expect("blocks").len();
        assert!(blocks < 1_000, "{main}: {blocks} blocks");
        let whys: Vec<&str> = report["unknown"]
            .as_array()
            .expect("unknown")
            .iter()
            .filter_map(|u| u["why"].as_str())
            .collect();
        assert!(
            whys.iter()
                .any(|why| why.contains("program levels") && why.contains("the run ends here")),
            "{main}: {whys:?}"
        );
        // The blocks after the calls never run: Y stays at 0.
        assert_eq!(report["axes"]["Y1"]["max"], 0.0, "{main}: {report}");
    }
}

/// Loops run as the control runs them, with their counters.
#[test]
fn loops_and_jumps_run_as_on_the_control() {
    let report = dry_run(
        &machine(""),
        "DEF INT I\nG0 X0 Y0 Z0\nFOR I=1 TO 4\nG91 G1 X10 F600\nENDFOR\nG90\n\
R1=0\nLOOP\nR1=R1+1\nIF R1>=3 GOTOF OUT\nG1 Y=R1*5\nENDLOOP\nOUT:\nREPEAT\nG91 Z-1\nUNTIL $P_EP[Z]<0 \nM30\n",
    );
    assert_eq!(report.axes[0].max, Some(40.0), "{:?}", report.unknown);
    assert_eq!(report.axes[1].max, Some(10.0));
    // The REPEAT's condition reads the position, unknown offline: left after one pass.
    assert_eq!(report.axes[2].min, Some(-1.0));
    // A FOR left by a jump starts anew when met again: the first pass
    // counts I = 1, 2, the second 1, 2, 3; R5 sums them (3 + 6), Z shows it.
    let again = dry_run(
        &machine(""),
        "DEF INT I\nG0 X0 Y0 Z0\nR2=0\nR5=0\nWHILE R2<2\nR2=R2+1\nFOR I=1 TO 10\nR5=R5+I\n\
IF I==R2+1 GOTOF NEXT\nENDFOR\nNEXT:\nENDWHILE\nG0 Z=R5\nM30\n",
    );
    assert_eq!(again.axes[2].max, Some(9.0), "{:?}", again.unknown);
    // REPEAT: a section from a label to the REPEAT, between two labels,
    // one block (REPEATB), each P times more after its first pass.
    let repeated = dry_run(
        &machine(""),
        "G0 X0 Y0 Z0\nR1=0\nR2=0\nSTART: R1=R1+1\nG91 G0 X1\nG90\nREPEAT START P=2\n\
FROM: R2=R2+1\nTO: R2=R2+10\nREPEAT FROM TO P=2\nONE: R2=R2+100\nREPEATB ONE P=3\n\
G0 Y=R1 Z=R2\nM30\n",
    );
    let (x, y, z) = (&repeated.axes[0], &repeated.axes[1], &repeated.axes[2]);
    assert_eq!(
        (x.max, y.max, z.max),
        (Some(3.0), Some(3.0), Some(433.0)),
        "{:?}",
        repeated.unknown
    );
    // CASE jumps to the branch of the selector's value, else to DEFAULT's.
    let case = |r1: u32| {
        let program = format!(
            "G0 X0 Y0 Z0\nR1={r1}\nCASE(R1) OF 1 GOTOF ONE 2 GOTOF TWO DEFAULT GOTOF OTHER\n\
ONE: G0 X10\nGOTOF END\nTWO: G0 X20\nGOTOF END\nOTHER: G0 X30\nEND: M30\n"
        );
        dry_run(&machine(""), &program).axes[0].max
    };
    assert_eq!(
        (case(1), case(2), case(7)),
        (Some(10.0), Some(20.0), Some(30.0))
    );
}

/// The system variables of the channel's state read what the program has
/// set: the tool it changed in (`$P_TOOLNO`), the one it programmed last
/// (`$P_TOOLP`), the cutting edge (`$P_TOOL`) and the settable frame
/// (`$P_UIFRNUM`: 0 for G500, 1 to 4 for G54 to G57, 5 to 99 for G505 to
/// G599). Before the program sets them they hold the control's state when
/// it starts, which is not known offline: named, not guessed.
#[test]
fn the_channel_state_the_program_set_is_read_back() {
    let program = "G0 X0 Y0 Z0\nG0 X=$P_TOOLNO\nT3 M6\nG0 X=$P_TOOLNO*10 Y=$P_TOOLP\n\
T5 D2\nG0 X=$P_TOOLNO Y=$P_TOOLP*10+$P_TOOL\nG55\nG0 X=$P_UIFRNUM*10\n\
G505\nG0 X=$P_UIFRNUM\nG500\nG0 X=$P_UIFRNUM\nM30\n";
    let mut ends: Vec<(usize, Option<f64>, Option<f64>)> = Vec::new();
    let report = dry_run_each(&machine(""), program, |end| {
        ends.push((end.line, end.mcs[0], end.mcs[1]));
    });
    let at = |line: usize| {
        let found = ends.iter().find(|(l, _, _)| *l == line);
        found.map(|&(_, x, y)| (x, y))
    };
    assert_eq!(at(4), Some((Some(30.0), Some(3.0))));
    assert_eq!(at(6), Some((Some(3.0), Some(52.0))));
    assert_eq!(at(8).map(|(x, _)| x), Some(Some(20.0)));
    assert_eq!(at(10).map(|(x, _)| x), Some(Some(5.0)));
    assert_eq!(at(12).map(|(x, _)| x), Some(Some(0.0)));
    // Before the program changes a tool, the one in the spindle is unknown.
    let told: Vec<(usize, &str)> = report
        .unknown
        .iter()
        .map(|u| (u.line, u.why.as_str()))
        .collect();
    assert!(
        told.iter()
            .any(|(line, why)| *line == 2 && why.contains("$P_TOOLNO")),
        "{told:?}"
    );
    assert!(
        !told
            .iter()
            .any(|(line, why)| *line > 2 && why.contains("unknown offline: `$P_")),
        "{told:?}"
    );
}

/// `check` on a machine reports the limits the dry run finds passed, as
/// `run` does (K007: exit 1), on the blocks that pass them; a suppression
/// on the block and `--ignore` take them away as any finding's.
#[test]
fn check_on_a_machine_reports_the_limits_passed() {
    let dir = scratch("check_limits");
    let data = dir.join("MACHINE.INI");
    std::fs::write(&data, machine("N36110 $MA_POS_LIMIT_PLUS[AX1]=50\n")).expect("write");
    let program = dir.join("P.MPF");
    std::fs::write(
        &program,
        "G0 X0 Y0 Z0\nG60 G0 X100\nG0 X0\nG0 X70 ; sinuprep: ignore K007\nM30\n",
    )
    .expect("write");
    let (data, program) = (
        data.to_str().expect("utf-8"),
        program.to_str().expect("utf-8"),
    );
    let check = |more: &[&str]| {
        let mut args = vec!["check", "--machine", data, "--format", "short", program];
        args.extend(more);
        command(&args, b"")
    };
    let found = check(&[]);
    assert_exit(&found, 1);
    let text = stdout(&found);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 1, "{text}");
    assert!(
        lines[0].ends_with(":2:1: error[K007] machine axis X1 reaches 100, 50 past its plus software limit 50 (MD36110 $MA_POS_LIMIT_PLUS): the control stops here with alarm 10720"),
        "{text}"
    );
    let ignored = check(&["--ignore", "K007"]);
    assert_exit(&ignored, 0);
    assert_eq!(stdout(&ignored), "");
}

/// The command: JSON as docs/guide.md gives it, the blocks streamed, SARIF,
/// and exit 1 where a limit is passed.
#[test]
fn the_command_prints_the_run() {
    let dir = scratch("run_command");
    let data = dir.join("MACHINE.INI");
    std::fs::write(
        &data,
        machine("N36110 $MA_POS_LIMIT_PLUS[AX1]=50\nN36100 $MA_POS_LIMIT_MINUS[AX1]=-10\n"),
    )
    .expect("write");
    let program = dir.join("P.MPF");
    std::fs::write(&program, "G0 X0 Y0 Z0\nG60 G0 X100\nG0 X0\nM30\n").expect("write");
    let (data, program) = (
        data.to_str().expect("utf-8"),
        program.to_str().expect("utf-8"),
    );
    let json = command(
        &["run", "--machine", data, "--format", "json", program],
        b"",
    );
    assert_exit(&json, 1);
    let read: serde_json::Value = serde_json::from_str(&stdout(&json)).expect("JSON");
    assert_eq!(read["violations"][0]["line"], 2);
    assert_eq!(read["violations"][0]["axis"], "X1");
    assert_eq!(read["violations"][0]["value"], 100.0);
    assert_eq!(read["violations"][0]["limit"], 50.0);
    assert_eq!(read["violations"][0]["side"], "plus");
    assert_eq!(
        read["axes"]["X1"]["limits"],
        serde_json::json!([-10.0, 50.0])
    );
    assert!(read["time_s"].as_f64().is_some_and(|t| t > 0.4));
    let blocks = command(
        &[
            "run",
            "--machine",
            data,
            "--format",
            "json",
            "--blocks",
            program,
        ],
        b"",
    );
    let read: serde_json::Value = serde_json::from_str(&stdout(&blocks)).expect("JSON");
    assert_eq!(read["blocks"][1]["line"], 2);
    assert_eq!(read["blocks"][1]["mcs"]["X1"], 100.0);
    assert_eq!(read["blocks"][1]["t_s"], 0.4);
    let sarif = command(
        &["run", "--machine", data, "--format", "sarif", program],
        b"",
    );
    let read: serde_json::Value = serde_json::from_str(&stdout(&sarif)).expect("SARIF");
    assert_eq!(read["runs"][0]["results"][0]["ruleId"], "K007");
    let human = command(&["run", "--machine", data, program], b"");
    let text = stdout(&human);
    assert!(text.contains("K007"), "{text}");
    assert!(
        text.contains("machine axis X1 reaches 100, 50 past its plus software limit 50"),
        "{text}"
    );
    // The page: self-contained, the axes over time, the two views, the tools.
    let page = dir.join("run.html");
    let html = command(
        &[
            "run",
            "--machine",
            data,
            "--html",
            page.to_str().expect("utf-8"),
            program,
        ],
        b"",
    );
    assert_exit(&html, 1);
    let page = std::fs::read_to_string(&page).expect("page written");
    assert!(page.starts_with("<!DOCTYPE html>") && page.ends_with("</html>\n"));
    assert_eq!(
        page.matches("<svg").count(),
        6,
        "X1, Y1, Z1 over time, two views, the time per tool"
    );
    assert!(page.contains("1 excursion past a software limit"));
    assert!(page.contains("limit 50"));
    assert!(
        !page.contains("<script") && !page.contains("http"),
        "nothing run, nothing fetched"
    );
    let within = command(
        &["run", "--machine", data, "-"],
        b"G0 X0 Y0 Z0\nG0 X20\nM30\n",
    );
    assert_exit(&within, 0);
}

/// The dry run of a pocket and four holes on a three-axis mill's own data
/// (tests/fixtures/run): read and checked by hand (the positions through
/// G54 and the tools' lengths, the times of the blocks against their closed
/// forms) before it was accepted.
#[test]
fn a_part_runs_dry_on_its_machine() {
    let args = [
        "run",
        "--machine",
        "tests/fixtures/run/MACHINE.INI",
        "tests/fixtures/run/PART.MPF",
    ];
    let human = command(&args, b"");
    assert_exit(&human, 1);
    insta::assert_snapshot!("run_human", stdout(&human));
    let mut json_args = args.to_vec();
    json_args.extend(["--format", "json"]);
    insta::assert_snapshot!("run_json", stdout(&command(&json_args, b"")));
}

/// Every program of the outside corpus and every sample and fixture runs to
/// its end (or to the block limit) on the test machine: no panic, whatever
/// the program holds, and every position it reports is a number.
#[test]
fn every_real_program_runs_without_a_panic() {
    let data = std::fs::read_to_string(support::repo().join("tests/fixtures/run/MACHINE.INI"))
        .expect("machine");
    let setup = Setup::of(&MachineData::read(data.as_bytes()));
    let options = Options {
        block_limit: 200_000,
        ..Options::default()
    };
    let mut files = support::corpus_files();
    files.extend(support::own_inputs());
    assert!(files.len() > 40);
    for path in files {
        let Ok(source) = std::fs::read(&path) else {
            continue;
        };
        let model = Model::of(&source);
        let programs = Programs::alone(&model);
        let report = run(&programs, &setup, &Supplied::default(), &options, |end| {
            assert!(
                end.mcs.iter().flatten().all(|v| v.is_finite()),
                "{}",
                path.display()
            );
        });
        assert!(
            report.time_s.is_finite() && report.time_s >= 0.0,
            "{}",
            path.display()
        );
    }
}

/// `run --format json --blocks` of `MAIN.MPF` on `MACHINE.INI` in `dir`.
fn run_with_blocks(dir: &std::path::Path) -> serde_json::Value {
    run_program_with_blocks(dir, "MAIN.MPF")
}

/// `run --format json --blocks` of `main` on `MACHINE.INI` in `dir`.
fn run_program_with_blocks(dir: &std::path::Path, main: &str) -> serde_json::Value {
    let json = command(
        &[
            "run",
            "--machine",
            dir.join("MACHINE.INI").to_str().expect("utf-8"),
            "--format",
            "json",
            "--blocks",
            dir.join(main).to_str().expect("utf-8"),
        ],
        b"",
    );
    serde_json::from_str(&stdout(&json)).expect("JSON")
}

/// Subprograms are followed as the control runs them: found beside the
/// program in any case, `L105` with `P` repetitions, a PROC given its
/// arguments by value, R parameters shared by every level, DEF variables
/// each level's own; a call nobody defines is named.
#[test]
fn subprograms_are_followed() {
    let dir = scratch("run_subprograms");
    std::fs::write(dir.join("MACHINE.INI"), machine("")).expect("write");
    std::fs::write(
        dir.join("MAIN.MPF"),
        "DEF REAL _X=1\nG0 X0 Y0 Z0\nR1=0\nL105 P3\nPOCKET(40, 5)\nG1 Y=R1 F600\nNOWHERE\nG0 X=_X\nM30\n",
    )
    .expect("write");
    std::fs::write(
        dir.join("l105.spf"),
        "DEF REAL _X=99\nR1=R1+1\nG91 G1 X10 F600\nG90\nM17\n",
    )
    .expect("write");
    std::fs::write(
        dir.join("POCKET.SPF"),
        "PROC POCKET(REAL _WIDTH, REAL _DEPTH)\nG1 X=_WIDTH Z=-_DEPTH F300\nRET\n",
    )
    .expect("write");
    let read = run_with_blocks(&dir);
    // Three runs of L105 take X to 30, POCKET to 40 and Z -5; R1 counts the runs.
    assert_eq!(read["axes"]["X1"]["max"], 40.0, "{read}");
    assert_eq!(read["axes"]["Z1"]["min"], -5.0);
    assert_eq!(read["axes"]["Y1"]["max"], 3.0);
    // The main program's _X is its own: back at X1 after the calls.
    let blocks = read["blocks"].as_array().expect("blocks");
    assert_eq!(blocks.last().expect("last")["mcs"]["X1"], 1.0);
    // The subprogram's blocks are passed with their own line numbers.
    assert!(
        blocks
            .iter()
            .any(|b| b["line"] == 3 && b["mcs"]["X1"] == 20.0),
        "{blocks:?}"
    );
    let unknown = read["unknown"].to_string();
    assert!(unknown.contains("`NOWHERE` is not followed"), "{unknown}");
    assert!(
        !unknown.contains("L105") && !unknown.contains("POCKET"),
        "{unknown}"
    );
    // A limit passed inside a subprogram is told on the subprogram's line.
    std::fs::write(
        dir.join("MACHINE.INI"),
        machine("N36110 $MA_POS_LIMIT_PLUS[AX1]=35\n"),
    )
    .expect("write");
    let human = command(
        &[
            "run",
            "--machine",
            dir.join("MACHINE.INI").to_str().expect("utf-8"),
            dir.join("MAIN.MPF").to_str().expect("utf-8"),
        ],
        b"",
    );
    assert_exit(&human, 1);
    let text = stdout(&human);
    assert!(text.contains("POCKET.SPF:2:1]"), "{text}");
    assert!(
        text.contains("machine axis X1 reaches 40, 5 past"),
        "{text}"
    );
}

/// `MCALL` calls its subprogram after each block that moves, with the
/// arguments it was given, until `MCALL` alone ends it; not after the
/// block that sets it, nor after the subprogram's own moves. A modal call
/// of a program that is not there is named once, at the MCALL.
#[test]
fn a_modal_call_follows_each_block_that_moves() {
    let dir = scratch("run_mcall");
    std::fs::write(dir.join("MACHINE.INI"), machine("")).expect("write");
    std::fs::write(
        dir.join("MAIN.MPF"),
        "G0 X0 Y0 Z10\nR1=5\nMCALL DRILL(R1)\nR1=7\nX10 Y10\nX20\nM5\nX30 Y20\n\
         MCALL\nX40\nMCALL NOWHERE(1)\nX50\nX60\nM30\n",
    )
    .expect("write");
    std::fs::write(
        dir.join("DRILL.SPF"),
        "PROC DRILL(REAL _DEPTH)\nG91 G1 Z=-_DEPTH F100\nG0 Z=_DEPTH\nG90\nRET\n",
    )
    .expect("write");
    let read = run_with_blocks(&dir);
    let blocks = read["blocks"].as_array().expect("blocks");
    // Each drilling, at the X it follows: the depth given at the MCALL (5),
    // not R1's later value.
    let drilled: Vec<f64> = blocks
        .iter()
        .filter(|b| b["program"] == "DRILL" && b["line"] == 2)
        .map(|b| {
            assert_eq!(b["mcs"]["Z1"], 5.0, "{b}");
            b["mcs"]["X1"].as_f64().expect("X1")
        })
        .collect();
    assert_eq!(drilled, [10.0, 20.0, 30.0], "{blocks:?}");
    assert_eq!(read["axes"]["Z1"]["min"], 5.0);
    assert_eq!(read["axes"]["X1"]["max"], 60.0);
    let unknown = read["unknown"].as_array().expect("unknown");
    let nowhere: Vec<&serde_json::Value> = unknown
        .iter()
        .filter(|u| u["why"].as_str().is_some_and(|w| w.contains("`NOWHERE`")))
        .collect();
    assert_eq!(nowhere.len(), 1, "{unknown:?}");
    assert_eq!(nowhere[0]["line"], 11);
    // Each drilling's time is in the run: 5 mm down at 100 mm/min, three times.
    let time = read["time_s"].as_f64().expect("time");
    assert!(time > 3.0 * 5.0 / 100.0 * 60.0, "{time}");
}

/// `EXTCALL` runs the program it names as a subprogram where the name is
/// written out: a path's last part, with or without `_N_` and `_SPF`, or
/// a file's name; one that is not there is named.
#[test]
fn an_external_call_is_followed_where_its_program_is_beside() {
    let dir = scratch("run_extcall");
    std::fs::write(dir.join("MACHINE.INI"), machine("")).expect("write");
    std::fs::write(
        dir.join("MAIN.MPF"),
        "G0 X0 Y0 Z0\nEXTCALL \"/_N_WKS_DIR/_N_PART_WPD/_N_ROUGH_SPF\"\n\
         EXTCALL(\"finish.spf\")\nEXTCALL \"NOTHERE\"\nM30\n",
    )
    .expect("write");
    std::fs::write(dir.join("ROUGH.SPF"), "G1 X10 F600\nM17\n").expect("write");
    std::fs::write(dir.join("finish.spf"), "G1 Y5 F600\nM17\n").expect("write");
    let read = run_with_blocks(&dir);
    assert_eq!(read["axes"]["X1"]["max"], 10.0, "{read}");
    assert_eq!(read["axes"]["Y1"]["max"], 5.0, "{read}");
    let unknown = read["unknown"].to_string();
    assert!(unknown.contains("`NOTHERE` is not followed"), "{unknown}");
    assert!(
        !unknown.contains("ROUGH") && !unknown.contains("FINISH"),
        "{unknown}"
    );
}

/// What the NC cannot know takes the seconds sinuprep.toml gives it, each
/// time it runs; a time that is no number of seconds is refused.
#[test]
fn the_times_the_user_gives_are_added() {
    let dir = scratch("run_times");
    std::fs::write(dir.join("MACHINE.INI"), machine("")).expect("write");
    std::fs::write(
        dir.join("sinuprep.toml"),
        "machine = \"MACHINE.INI\"\n[run]\ntimes = { M06 = 7.5, cycle800 = 12 }\n",
    )
    .expect("write");
    std::fs::write(dir.join("P.MPF"), "T1 M6\nT2 M6\nCYCLE800()\nM30\n").expect("write");
    let program = dir.join("P.MPF");
    let json = command(
        &["run", "--format", "json", program.to_str().expect("utf-8")],
        b"",
    );
    assert_exit(&json, 0);
    let read: serde_json::Value = serde_json::from_str(&stdout(&json)).expect("JSON");
    assert_eq!(read["time_s"], 27.0, "{read}");
    assert!(
        read["assumptions"].to_string().contains("M6 takes 7.5 s"),
        "{read}"
    );
    std::fs::write(dir.join("sinuprep.toml"), "[run]\ntimes = { M6 = -1 }\n").expect("write");
    let refused = command(&["run", program.to_str().expect("utf-8")], b"");
    assert_exit(&refused, 2);
}

/// A five-axis machine's data: X, Y, Z and the rotary axes B and C (their
/// machine names as the swivel record names them, no limits), with
/// `records` and `extra` (frames, tools).
fn five_axis(extra: &str) -> String {
    let mut text = String::from(
        "%_N_INITIAL_INI\nN10240 $MN_SCALING_SYSTEM_IS_METRIC=1\nN10600 $MN_FRAME_ANGLE_INPUT_MODE=1\n",
    );
    let names = ["X1", "Y1", "Z1", "B", "C"];
    for (k, name) in names.iter().enumerate() {
        text.push_str(&format!(
            "N10000 $MN_AXCONF_MACHAX_NAME_TAB[{k}]=\"{name}\"\n"
        ));
    }
    text.push_str("CHANDATA(1)\nN22550 $MC_TOOL_CHANGE_MODE=1\n");
    for (k, name) in ["X", "Y", "Z", "B", "C"].iter().enumerate() {
        text.push_str(&format!(
            "N20070 $MC_AXCONF_MACHAX_USED[{k}]={}\nN20080 $MC_AXCONF_CHANAX_NAME_TAB[{k}]=\"{name}\"\n",
            k + 1
        ));
    }
    for (k, name) in names.iter().enumerate() {
        let rotary = u8::from(k >= 3);
        text.push_str(&format!(
            "N30300 $MA_IS_ROT_AX[{name}]={rotary}\nN32000 $MA_MAX_AX_VELO[{name}]=20000.\n\
N32300 $MA_MAX_AX_ACCEL[0,{name}]=2.\nN32431 $MA_MAX_AX_JERK[0,{name}]=40.\n"
        ));
    }
    text.push_str(extra);
    text.push_str("M17\n");
    text
}

/// `R(v, angle)`, right-handed, degrees: Rodrigues' formula written out,
/// not the library's.
fn rodrigues(v: [f64; 3], angle: f64) -> Matrix3<f64> {
    let k = Vector3::from(v).normalize();
    let (s, c) = angle.to_radians().sin_cos();
    let cross = Matrix3::new(0.0, -k.z, k.y, k.z, 0.0, -k.x, -k.y, k.x, 0.0);
    Matrix3::identity() + cross * s + cross * cross * (1.0 - c)
}

/// A swivel record's axes and offset vectors as the oracle reads them.
struct Kinematic {
    letter: char,
    vectors: [[f64; 3]; 2],
    offsets: [[f64; 3]; 4],
}

/// Where the tool tip is on the workpiece (its unswivelled system), and the
/// tool's direction there, for the holder at `m` and the rotary axes at
/// `angles`: each pivot placed in turn from the machine's side, as the
/// record's offset vectors describe the machine (reference/kinematics.md
/// §1.2), not through the run's carrier.
fn forward(
    k: &Kinematic,
    m: Vector3<f64>,
    angles: [f64; 2],
    tool: Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    let [l1, l2, l3, _] = k.offsets.map(Vector3::from);
    let (r1, r2) = (
        rodrigues(k.vectors[0], angles[0]),
        rodrigues(k.vectors[1], angles[1]),
    );
    let along = tool.normalize();
    match k.letter {
        'T' => {
            let pivot_1 = m - l1;
            let pivot_2 = pivot_1 - r1 * l2;
            let tip = pivot_2 - r1 * r2 * (l3 + tool);
            (tip, r1 * r2 * along)
        }
        'P' => {
            // A point x of the workpiece at rest goes to p1 + R1 (p2 - p1 +
            // R2 (x - p2)): turned about axis 2's pivot, then axis 1's.
            let (p1, p2) = (l2, l2 + l3);
            let tip = m - tool;
            let x = p2 + r2.transpose() * (r1.transpose() * (tip - p1) - (p2 - p1));
            (x, (r1 * r2).transpose() * along)
        }
        _ => {
            // Axis 1 turns the head about its pivot, axis 2 the table about its own.
            let tip = m - l1 - r1 * (l2 + tool);
            let x = l3 + r2.transpose() * (tip - l3);
            (x, r2.transpose() * r1 * along)
        }
    }
}

/// The holder's machine position and the rotary axes `names` (B or C of
/// [`five_axis`]) at the end of the block on 1-based `line`.
fn holder_at(ends: &Ends, line: usize, names: [&str; 2]) -> (Vector3<f64>, [f64; 2]) {
    let (_, mcs) = ends
        .iter()
        .find(|(at, _)| *at == line)
        .expect("the block's end");
    let m = Vector3::new(
        mcs[0].expect("known"),
        mcs[1].expect("known"),
        mcs[2].expect("known"),
    );
    let rotary = names.map(|name| mcs[if name == "B" { 3 } else { 4 }].expect("the rotary axis"));
    (m, rotary)
}

/// A head, a table and a mixed machine, their axes and offset vectors.
fn oracle_kinematics() -> [Kinematic; 3] {
    [
        Kinematic {
            letter: 'T',
            vectors: [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0]],
            offsets: [
                [-10.0, 5.0, -320.0],
                [10.0, 0.0, 120.0],
                [0.0, -5.0, 200.0],
                [0.0; 3],
            ],
        },
        Kinematic {
            letter: 'P',
            vectors: [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            offsets: [
                [0.0; 3],
                [150.0, 200.0, -100.0],
                [0.0, 20.0, 60.0],
                [-150.0, -220.0, 40.0],
            ],
        },
        Kinematic {
            letter: 'M',
            vectors: [[0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            offsets: [
                [0.0, 0.0, -250.0],
                [0.0, 0.0, 250.0],
                [120.0, 80.0, -50.0],
                [-120.0, -80.0, 50.0],
            ],
        },
    ]
}

/// The swivel data record 1 ("SWIVEL") of `k`, as the control's files write it.
fn record_text(k: &Kinematic) -> String {
    let v = |i: usize, j: usize| k.vectors[i][j];
    let l = |i: usize, j: usize| k.offsets[i][j];
    let mut records = format!(
        "$TC_CARR23[1]=\"{}\" $TC_CARR34[1]=\"SWIVEL\" $TC_CARR35[1]=\"{}\" $TC_CARR36[1]=\"{}\"\n",
        k.letter,
        rotary_name(k, 0),
        rotary_name(k, 1),
    );
    for (i, first) in [(0, 7), (1, 10)] {
        records.push_str(&format!(
            "$TC_CARR{}[1]={} $TC_CARR{}[1]={} $TC_CARR{}[1]={}\n",
            first,
            v(i, 0),
            first + 1,
            v(i, 1),
            first + 2,
            v(i, 2)
        ));
    }
    for (i, first) in [(0, 1), (1, 4), (2, 15), (3, 18)] {
        records.push_str(&format!(
            "$TC_CARR{}[1]={} $TC_CARR{}[1]={} $TC_CARR{}[1]={}\n",
            first,
            l(i, 0),
            first + 1,
            l(i, 1),
            first + 2,
            l(i, 2)
        ));
    }
    records
}

/// The name of `k`'s rotary axis `i`: C about Z, else B.
fn rotary_name(k: &Kinematic, i: usize) -> &'static str {
    if k.vectors[i][2] == 1.0 {
        "C"
    } else {
        "B"
    }
}

/// CYCLE800 on a head, a table and a mixed machine: after the swivel, each
/// programmed point's machine position, with the rotary axes the run turned
/// to, puts the tool tip (by the independent chain above) on the point
/// through G54, the swivel frame (`_X0`, the `_MODE` turns, `_X1`) and the
/// TRANS inside it, and the tool along the plane's normal.
#[test]
fn a_swivel_puts_the_tool_on_the_swivelled_plane() {
    let kinematics = oracle_kinematics();
    let modes: [(u32, [usize; 3]); 3] = [(57, [0, 1, 2]), (27, [2, 1, 0]), (39, [2, 0, 1])];
    let unit = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mut numbers = Numbers(800);
    for k in &kinematics {
        for case in 0..12 {
            let (code, axes) = modes[case % 3];
            let angles = [
                numbers.between(-60.0, 60.0),
                numbers.between(-60.0, 60.0),
                numbers.between(-60.0, 60.0),
            ];
            let zero = [
                numbers.between(-50.0, 50.0),
                numbers.between(-50.0, 50.0),
                numbers.between(-20.0, 20.0),
            ];
            let after = [
                numbers.between(-10.0, 10.0),
                numbers.between(-10.0, 10.0),
                numbers.between(-10.0, 10.0),
            ];
            let g54 = [
                numbers.between(-200.0, 200.0),
                numbers.between(-200.0, 200.0),
                numbers.between(-300.0, -100.0),
            ];
            let trans = [
                numbers.between(-5.0, 5.0),
                numbers.between(-5.0, 5.0),
                numbers.between(-5.0, 5.0),
            ];
            let length = numbers.between(50.0, 150.0);
            let direction = if case % 2 == 0 { -1 } else { 1 };
            let points: Vec<[f64; 3]> = (0..3)
                .map(|_| {
                    [
                        numbers.between(-40.0, 40.0),
                        numbers.between(-40.0, 40.0),
                        numbers.between(0.0, 30.0),
                    ]
                })
                .collect();
            let records = record_text(k);
            let data = five_axis(&format!(
                "{records}$P_UIFR[1,X,TR]={}\n$P_UIFR[1,Y,TR]={}\n$P_UIFR[1,Z,TR]={}\n\
$TC_DP1[1,1]=120\n$TC_DP3[1,1]={length}\n",
                g54[0], g54[1], g54[2]
            ));
            let mut program = format!(
                "G54 T1 D1 M6\nTRANS X{} Y{} Z{}\nCYCLE800(0,\"SWIVEL\",0,{code},{},{},{},{},{},{},{},{},{},{direction})\n",
                trans[0], trans[1], trans[2], zero[0], zero[1], zero[2], angles[0], angles[1], angles[2],
                after[0], after[1], after[2]
            );
            for p in &points {
                program.push_str(&format!("G1 X{} Y{} Z{} F1000\n", p[0], p[1], p[2]));
            }
            program.push_str("M30\n");

            let (report, ends) = dry_run_ends(&data, &program);
            let what = format!("{} case {case}: {program}{:?}", k.letter, report.unknown);
            assert!(
                report.unknown.iter().all(|u| !u.why.contains("CYCLE800")),
                "{what}"
            );
            // The plane: the _MODE turns about the turned axes, in order.
            let plane = (0..3).fold(Matrix3::identity(), |r, i| {
                r * rodrigues(unit[axes[i]], angles[i])
            });
            for (i, p) in points.iter().enumerate() {
                let names = [rotary_name(k, 0), rotary_name(k, 1)];
                let (m, turned) = holder_at(&ends, 4 + i, names);
                let (tip, tool) = forward(k, m, turned, along_z(length));
                let expected = Vector3::from(g54)
                    + Vector3::from(zero)
                    + plane * (Vector3::from(after) + Vector3::from(trans) + Vector3::from(*p));
                assert!(
                    (tip - expected).norm() < 1e-9,
                    "{what}: tip {tip} != {expected}"
                );
                let normal = plane * Vector3::z();
                assert!(
                    (tool - normal).norm() < 1e-9,
                    "{what}: tool {tool} != {normal}"
                );
            }
        }
    }
}

/// Where `forward` puts the holder for the tool tip on the workpiece's
/// point `x` with the rotary axes at `angles`: its chain solved for the
/// holder, in closed form.
fn holder(k: &Kinematic, x: Vector3<f64>, angles: [f64; 2], tool: Vector3<f64>) -> Vector3<f64> {
    let [l1, l2, l3, _] = k.offsets.map(Vector3::from);
    let (r1, r2) = (
        rodrigues(k.vectors[0], angles[0]),
        rodrigues(k.vectors[1], angles[1]),
    );
    match k.letter {
        'T' => x + l1 + r1 * l2 + r1 * r2 * (l3 + tool),
        'P' => {
            let (p1, p2) = (l2, l2 + l3);
            p1 + r1 * (r2 * (x - p2) + p2 - p1) + tool
        }
        _ => l3 + r2 * (x - l3) + l1 + r1 * (l2 + tool),
    }
}

/// The tool of `length` in plane G17: along Z.
fn along_z(length: f64) -> Vector3<f64> {
    tool_in_plane(length, 0)
}

/// The tool of `length` in plane `plane` (0: G17, 1: G18, 2: G19): along
/// the plane's infeed axis, Z, Y or X. A change of plane turns the tool's
/// length and its basic orientation alike (Function Manual Basic
/// Functions W1, "Basic tool orientation").
fn tool_in_plane(length: f64, plane: usize) -> Vector3<f64> {
    let mut tool = Vector3::zeros();
    tool[[2, 1, 0][plane]] = length;
    tool
}

/// TRAORI with the kinematics of a swivel data record (MD24100 type 72,
/// the record MD24582 names) on a head, a table and a mixed machine: at
/// each block's end the rotary axes stand where programmed and the holder
/// puts the tool tip (by the independent chain) on the point through G54;
/// along a block, where the linear axes follow curves, the run's travel of
/// each machine axis is the one a fine sampling of the chain finds, the
/// rotary axes turning linearly (ORIAXES, G group 51 chosen by MD21104).
#[test]
fn under_traori_the_tip_stays_on_the_programmed_point() {
    let mut numbers = Numbers(900);
    for k in &oracle_kinematics() {
        for case in 0..16 {
            let (g54, length) = g54_and_tool_length(&mut numbers);
            let mut point = || {
                (
                    [
                        numbers.between(-40.0, 40.0),
                        numbers.between(-40.0, 40.0),
                        numbers.between(0.0, 30.0),
                    ],
                    [numbers.between(-60.0, 60.0), numbers.between(-90.0, 90.0)],
                )
            };
            let points = [point(), point()];
            let vector = [numbers.between(-0.6, 0.6), numbers.between(-0.6, 0.6), 1.0];
            let last = [
                numbers.between(-40.0, 40.0),
                numbers.between(-40.0, 40.0),
                numbers.between(0.0, 30.0),
            ];
            let data = |limits: &str| traori_machine(k, g54, length, limits);
            let names = [rotary_name(k, 0), rotary_name(k, 1)];
            let mut program = String::from("G54 T1 D1 M6\nTRAORI ORIAXES\n");
            for (p, angles) in &points {
                program.push_str(&format!(
                    "G1 X{} Y{} Z{} {}{} {}{} F1000\n",
                    p[0], p[1], p[2], names[0], angles[0], names[1], angles[1]
                ));
            }
            program.push_str(&format!(
                "G1 X{} Y{} Z{} A3={} B3={} C3={}\nM30\n",
                last[0], last[1], last[2], vector[0], vector[1], vector[2]
            ));
            let dry = |limits: &str| {
                let data = data(limits);
                dry_run_ends(&data, &program)
            };
            let (report, ends) = dry("");
            let what = format!("{} case {case}: {program}{:?}", k.letter, report.unknown);
            assert!(
                report.unknown.iter().all(|u| !u.why.contains("TRAORI")),
                "{what}"
            );
            for (i, (p, angles)) in points.iter().enumerate() {
                let (m, turned) = holder_at(&ends, 3 + i, names);
                assert_near(turned[0], angles[0], 1e-12, &what);
                assert_near(turned[1], angles[1], 1e-12, &what);
                let (tip, _) = forward(k, m, turned, along_z(length));
                let expected = Vector3::from(g54) + Vector3::from(*p);
                assert!(
                    (tip - expected).norm() < 1e-9,
                    "{what}: tip {tip} != {expected}"
                );
            }
            // A direction by its vector: the tool along it, the tip on the point.
            let (m, turned) = holder_at(&ends, 5, names);
            let (tip, tool) = forward(k, m, turned, along_z(length));
            let expected = Vector3::from(g54) + Vector3::from(last);
            assert!(
                (tip - expected).norm() < 1e-9,
                "{what}: tip {tip} != {expected}"
            );
            let direction = Vector3::from(vector).normalize();
            assert!(
                (tool - direction).norm() < 1e-9,
                "{what}: tool {tool} != {direction}"
            );
            // The second and third blocks' ways: the tip on the line between
            // their ends, the axes turning linearly; the first block's end is
            // where they start.
            let ways = [
                (points[0].0, points[0].1, points[1].0, points[1].1),
                (points[1].0, points[1].1, last, turned),
            ];
            let mut lowest = [f64::INFINITY; 3];
            let mut highest = [f64::NEG_INFINITY; 3];
            for (from, from_angles, to, to_angles) in ways {
                for i in 0..=20_000 {
                    let s = f64::from(i) / 20_000.0;
                    let x = Vector3::from(g54)
                        + Vector3::from(from)
                        + (Vector3::from(to) - Vector3::from(from)) * s;
                    let angles =
                        [0, 1].map(|j| from_angles[j] + (to_angles[j] - from_angles[j]) * s);
                    let m = holder(k, x, angles, along_z(length));
                    let (tip, _) = forward(k, m, angles, along_z(length));
                    assert!((tip - x).norm() < 1e-9, "the oracle's own round trip");
                    for a in 0..3 {
                        lowest[a] = lowest[a].min(m[a]);
                        highest[a] = highest[a].max(m[a]);
                    }
                }
            }
            limits_found_at_the_extremes(&dry, lowest, highest, &what);
            travel_is(&report, lowest, highest, &format!("{what} {program}"));
        }
    }
}

/// An arc (G2, G3, a helix too) under TRAORI, in each plane (G17, G18,
/// G19), its centre given by the plane's I, J, K, by its radius (CR=) or
/// by the angle it sweeps (AR=):
/// the tool tip on the circle through G54, the rotary axes standing still or turning linearly
/// (ORIAXES); the run's travel of each machine axis is the one a fine
/// sampling of the independent chain along the circle finds (a full
/// circle and a helix of two turns more among them), a limit just inside
/// it is found and one just outside is not; the block's time is the
/// circle's length at the feed, with a start and a stop.
#[test]
fn under_traori_an_arc_is_followed_along_its_circle() {
    const SAMPLES: u32 = 20_000;
    let mut numbers = Numbers(1100);
    for k in &oracle_kinematics() {
        for case in 0..10 {
            let (g54, length) = g54_and_tool_length(&mut numbers);
            // A full circle (the end its start), and two turns more (TURN=2).
            let (full, turns) = (case == 8, u32::from(case == 9) * 2);
            let start = [
                numbers.between(-40.0, 40.0),
                numbers.between(-40.0, 40.0),
                numbers.between(0.0, 30.0),
            ];
            let from_angles = [numbers.between(-60.0, 60.0), numbers.between(-90.0, 90.0)];
            // The centre from the start (I, J), the angle swept, the rise.
            let offset = [numbers.between(-30.0, 30.0), numbers.between(-30.0, 30.0)];
            let sweep = match full {
                true => std::f64::consts::TAU,
                false => numbers.between(20.0, 340.0).to_radians(),
            } + std::f64::consts::TAU * f64::from(turns);
            let rise = numbers.between(-10.0, 10.0);
            let clockwise = case % 2 == 0;
            // Every other pair of cases the rotary axes turn with the arc.
            let turning = case % 4 >= 2 || turns > 0;
            let to_angles = if turning {
                [numbers.between(-60.0, 60.0), numbers.between(-90.0, 90.0)]
            } else {
                from_angles
            };
            // The plane: its first axis, its second, the one across it.
            let plane = case % 3;
            let [first, second, across] = [[0, 1, 2], [2, 0, 1], [1, 2, 0]][plane];
            // The radius alone (CR=, negative past a half circle) where the
            // end and the radius name the circle.
            let by_radius = case == 1 || case == 5;
            // The angle swept alone (AR=) with the end.
            let by_angle = case == 3 || case == 7;
            let centre = [start[first] + offset[0], start[second] + offset[1]];
            let radius = offset[0].hypot(offset[1]);
            let phase = (-offset[1]).atan2(-offset[0]);
            let direction = if clockwise { -1.0 } else { 1.0 };
            let tip = |s: f64| {
                let angle = phase + direction * sweep * s;
                let mut tip = Vector3::from(start);
                tip[first] = centre[0] + radius * angle.cos();
                tip[second] = centre[1] + radius * angle.sin();
                tip[across] = start[across] + rise * s;
                tip
            };
            let end = tip(1.0);
            let names = [rotary_name(k, 0), rotary_name(k, 1)];
            let mut program = format!(
                "G54 G{} T1 D1 M6\nTRAORI ORIAXES\nG1 X{} Y{} Z{} {}{} {}{} F1000\n",
                17 + plane,
                start[0],
                start[1],
                start[2],
                names[0],
                from_angles[0],
                names[1],
                from_angles[1]
            );
            let centre_words = match (by_radius, by_angle) {
                (true, _) if sweep > std::f64::consts::PI => format!("CR=-{radius}"),
                (true, _) => format!("CR={radius}"),
                (_, true) => format!("AR={}", sweep.to_degrees()),
                _ => {
                    let letters = ["I", "J", "K"];
                    format!(
                        "{}{} {}{}",
                        letters[first], offset[0], letters[second], offset[1]
                    )
                }
            };
            program.push_str(&format!(
                "G{} X{} Y{} Z{} {centre_words}",
                if clockwise { 2 } else { 3 },
                end.x,
                end.y,
                end.z,
            ));
            if turning {
                program.push_str(&format!(
                    " {}{} {}{}",
                    names[0], to_angles[0], names[1], to_angles[1]
                ));
            }
            if turns > 0 {
                program.push_str(&format!(" TURN={turns}"));
            }
            program.push_str(" F600\nM30\n");
            let data = |limits: &str| traori_machine(k, g54, length, limits);
            let dry = |limits: &str| dry_run_ends(&data(limits), &program);
            let (report, ends) = dry("");
            let what = format!("{} case {case}: {program}{:?}", k.letter, report.unknown);
            // Nothing on the arc's block is left out or taken as unknown.
            assert!(report.unknown.iter().all(|u| u.line != 4), "{what}");
            // At the arc's end: the rotary axes where programmed, the tip on
            // the end through G54.
            let (m, turned) = holder_at(&ends, 4, names);
            assert_near(turned[0], to_angles[0], 1e-12, &what);
            assert_near(turned[1], to_angles[1], 1e-12, &what);
            let tool = tool_in_plane(length, plane);
            let (at_end, _) = forward(k, m, turned, tool);
            assert!(
                (at_end - Vector3::from(g54) - end).norm() < 1e-9,
                "{what}: tip {at_end}"
            );
            let mut lowest = [f64::INFINITY; 3];
            let mut highest = [f64::NEG_INFINITY; 3];
            for i in 0..=SAMPLES {
                let s = f64::from(i) / f64::from(SAMPLES);
                let x = Vector3::from(g54) + tip(s);
                let angles = [0, 1].map(|j| from_angles[j] + (to_angles[j] - from_angles[j]) * s);
                let m = holder(k, x, angles, tool);
                for a in 0..3 {
                    lowest[a] = lowest[a].min(m[a]);
                    highest[a] = highest[a].max(m[a]);
                }
            }
            // The first block's way, from the start (where the run begins
            // to know the axes) is its end alone.
            let (m, _) = holder_at(&ends, 3, names);
            for a in 0..3 {
                lowest[a] = lowest[a].min(m[a]);
                highest[a] = highest[a].max(m[a]);
            }
            travel_is(&report, lowest, highest, &what);
            limits_found_at_the_extremes(&dry, lowest, highest, &what);
            // The tip's way along the circle at 600 mm/min, with no more
            // than a start and a stop (the first block, from an unknown
            // start, has no time).
            let arc_length = (radius * sweep).hypot(rise);
            assert!(
                (arc_length / 10.0 - 1e-9..arc_length / 10.0 + 0.5).contains(&report.time_s),
                "{what}: {} s for {arc_length} mm",
                report.time_s
            );
        }
    }
}

/// A G54 of the oracle's TRAORI tests and the tool's length.
fn g54_and_tool_length(numbers: &mut Numbers) -> ([f64; 3], f64) {
    let g54 = [
        numbers.between(-200.0, 200.0),
        numbers.between(-200.0, 200.0),
        numbers.between(-300.0, -100.0),
    ];
    (g54, numbers.between(50.0, 150.0))
}

/// The five-axis machine with TRAORI on the record of `k` (ORIAXES by
/// MD21104), `g54` and a tool of `length`; `limits` lines of data first.
fn traori_machine(k: &Kinematic, g54: [f64; 3], length: f64, limits: &str) -> String {
    five_axis(&format!(
        "{limits}{}CHANDATA(1)\n$MC_TRAFO_TYPE_1=72\n$MC_TRAFO5_TCARR_NO_1=1\n$MC_ORI_IPO_WITH_G_CODE=1\n\
$P_UIFR[1,X,TR]={}\n$P_UIFR[1,Y,TR]={}\n$P_UIFR[1,Z,TR]={}\n$TC_DP1[1,1]=120\n$TC_DP3[1,1]={length}\n",
        record_text(k),
        g54[0],
        g54[1],
        g54[2]
    ))
}

/// The run's travel of X1, Y1, Z1 is `lowest`..`highest`, to 1e-6.
fn travel_is(report: &Report, lowest: [f64; 3], highest: [f64; 3], what: &str) {
    for a in 0..3 {
        let travel = &report.axes[a];
        assert_near(
            travel.min.expect("min"),
            lowest[a],
            1e-6,
            &format!("{what} axis {a}"),
        );
        assert_near(
            travel.max.expect("max"),
            highest[a],
            1e-6,
            &format!("{what} axis {a}"),
        );
    }
}

/// A limit a micrometre inside the way's extreme (`lowest`, `highest` of
/// X1, Y1, Z1) is passed, one a micrometre outside it is not, on either
/// side: `dry` runs the program on the machine with a line of data added.
fn limits_found_at_the_extremes(
    dry: &impl Fn(&str) -> (Report, Ends),
    lowest: [f64; 3],
    highest: [f64; 3],
    what: &str,
) {
    for (a, name) in ["X1", "Y1", "Z1"].iter().enumerate() {
        for (side, extreme, sign, md) in [
            (Side::Plus, highest[a], 1.0, "N36110 $MA_POS_LIMIT_PLUS"),
            (Side::Minus, lowest[a], -1.0, "N36100 $MA_POS_LIMIT_MINUS"),
        ] {
            let inside = format!("{md}[{name}]={}\n", extreme - sign * 1e-3);
            let (limited, _) = dry(&inside);
            assert!(
                limited
                    .violations
                    .iter()
                    .any(|v| v.axis == *name && v.side == side),
                "{what}: {inside} {:?}",
                limited.violations
            );
            let outside = format!("{md}[{name}]={}\n", extreme + sign * 1e-3);
            let (clear, _) = dry(&outside);
            assert!(
                clear.violations.is_empty(),
                "{what}: {outside} {:?}",
                clear.violations
            );
        }
    }
}

/// Under ORIWKS (the basic setting, MD21104 not in the data) a tool
/// direction programmed as a vector is reached on the great circle from the
/// one before: on a head (C about Z, then B about Y, tool `Rz(C) Ry(B) Z`),
/// the axes turned onto the vector, and the run's travel
/// of each linear axis is the one the independent chain finds with the
/// direction slerped and the axes solved for it in closed form (the
/// solution nearest the axes' linear way), sampled 20,000 times and,
/// where the axes turn more than 0.005 degrees between two samples (near
/// the pole C turns fast), finer.
#[test]
fn under_oriwks_the_tool_turns_on_a_great_circle() {
    const SAMPLES: u32 = 20_000;
    let head = &oracle_kinematics()[0];
    let mut numbers = Numbers(1000);
    for case in 0..12 {
        let length = numbers.between(50.0, 150.0);
        let mut point = || {
            (
                [
                    numbers.between(-40.0, 40.0),
                    numbers.between(-40.0, 40.0),
                    numbers.between(0.0, 30.0),
                ],
                // C, B.
                [numbers.between(-90.0, 90.0), numbers.between(10.0, 60.0)],
            )
        };
        let (from, to) = (point(), point());
        let data = five_axis(&format!(
            "{}CHANDATA(1)\n$MC_TRAFO_TYPE_1=72\n$MC_TRAFO5_TCARR_NO_1=1\n\
$TC_DP1[1,1]=120\n$TC_DP3[1,1]={length}\n",
            record_text(head)
        ));
        let direction = |[c, b]: [f64; 2]| {
            let (c, b) = (c.to_radians(), b.to_radians());
            Vector3::new(b.sin() * c.cos(), b.sin() * c.sin(), b.cos())
        };
        // The first end by the axes' positions, the second by a vector.
        let (p, [c, b]) = &from;
        let mut program = format!(
            "T1 D1 M6\nTRAORI\nG1 X{} Y{} Z{} C{c} B{b} F1000\n",
            p[0], p[1], p[2]
        );
        let (p, d1) = (&to.0, direction(to.1));
        program.push_str(&format!(
            "G1 X{} Y{} Z{} A3={} B3={} C3={}\nM30\n",
            p[0], p[1], p[2], d1.x, d1.y, d1.z
        ));
        let (report, ends) = dry_run_ends(&data, &program);
        let what = format!("case {case}: {program}{:?}", report.unknown);
        // Where the run turned the axes for the vector: onto it.
        let (_, turned) = holder_at(&ends, 4, ["C", "B"]);
        assert!((direction(turned) - d1).norm() < 1e-9, "{what}");
        let to = (to.0, turned);
        let d0 = direction(from.1);
        let angle = d0.dot(&d1).clamp(-1.0, 1.0).acos();
        // The axes and the holder at share `s` of the block.
        let at = |s: f64| {
            let d = (d0 * ((1.0 - s) * angle).sin() + d1 * (s * angle).sin()) / angle.sin();
            let linear = [0, 1].map(|j| from.1[j] + (to.1[j] - from.1[j]) * s);
            let b = d.z.clamp(-1.0, 1.0).acos().to_degrees();
            let c = d.y.atan2(d.x).to_degrees();
            let near = |c: f64| c + 360.0 * ((linear[0] - c) / 360.0).round();
            let solutions = [[near(c), b], [near(c + 180.0), -b]];
            let off = |x: &[f64; 2]| (x[0] - linear[0]).abs().max((x[1] - linear[1]).abs());
            let turned = if off(&solutions[0]) <= off(&solutions[1]) {
                solutions[0]
            } else {
                solutions[1]
            };
            assert!(
                (direction(turned) - d.normalize()).norm() < 1e-9,
                "the oracle's own solution"
            );
            let x = Vector3::from(from.0) + (Vector3::from(to.0) - Vector3::from(from.0)) * s;
            (turned, holder(head, x, turned, along_z(length)))
        };
        let mut lowest = [f64::INFINITY; 3];
        let mut highest = [f64::NEG_INFINITY; 3];
        let mut seen = |m: Vector3<f64>| {
            for a in 0..3 {
                lowest[a] = lowest[a].min(m[a]);
                highest[a] = highest[a].max(m[a]);
            }
        };
        // Evenly, and finer where the axes turn more than 0.005 degrees
        // between two samples (near the pole C turns fast).
        let mut previous = at(0.0);
        seen(previous.1);
        for i in 1..=SAMPLES {
            let (s0, s1) = (
                f64::from(i - 1) / f64::from(SAMPLES),
                f64::from(i) / f64::from(SAMPLES),
            );
            let next = at(s1);
            let turn = (0..2)
                .map(|j| (next.0[j] - previous.0[j]).abs())
                .fold(0.0, f64::max);
            let finer = (turn / 0.005).ceil().clamp(1.0, 100_000.0) as u32;
            for k in 1..finer {
                seen(at(s0 + (s1 - s0) * f64::from(k) / f64::from(finer)).1);
            }
            seen(next.1);
            previous = next;
        }
        travel_is(&report, lowest, highest, &what);
    }
}

/// What TRAORI cannot follow is named on its block: no orientation
/// transformation in the data, a type whose kinematics are the TRAFO5 data,
/// an orientation on a cone (ORICONCW); TRAFOOF ends the transformation.
#[test]
fn traori_names_what_it_does_not_follow() {
    let head = &oracle_kinematics()[0];
    let whys = |trafo: &str, program: &str| -> Vec<(usize, String)> {
        let data = five_axis(&format!("{}CHANDATA(1)\n{trafo}", record_text(head)));
        let report = dry_run(&data, program);
        report
            .unknown
            .into_iter()
            .map(|u| (u.line, u.why))
            .collect()
    };
    let program = "G0 X0 Y0 Z0 B0 C0\nTRAORI\nORICONCW\nG1 X10 B10 F100\nTRAFOOF\nM30\n";
    let none = whys("", program);
    assert!(
        none.iter()
            .any(|(line, why)| *line == 2 && why.contains("no orientation transformation 1")),
        "{none:?}"
    );
    let generic = whys("$MC_TRAFO_TYPE_1=24\n", program);
    assert!(
        generic.iter().any(|(line, why)| *line == 2
            && why.contains("type 24")
            && why.contains("not modelled")),
        "{generic:?}"
    );
    // An arc from rotary axes never positioned: taken at the block's end, named.
    let from_unknown = whys(
        "$MC_TRAFO_TYPE_1=72\n$MC_TRAFO5_TCARR_NO_1=1\n",
        "TRAORI\nG1 X0 Y0 Z0 F100\nG2 X10 Y0 I5 J0 B10 C0\nM30\n",
    );
    assert!(
        from_unknown.iter().any(|(line, why)| *line == 3
            && why.contains("an arc under TRAORI from rotary axes whose positions are unknown")),
        "{from_unknown:?}"
    );
    let carrier = whys("$MC_TRAFO_TYPE_1=72\n$MC_TRAFO5_TCARR_NO_1=1\n", program);
    assert!(carrier.iter().all(|(line, _)| *line != 2), "{carrier:?}");
    assert!(
        carrier
            .iter()
            .any(|(line, why)| *line == 3 && why.contains("a cone or a curve")),
        "{carrier:?}"
    );
}

/// A swivel the record allows but the machine data's software limits do
/// not is a K007 finding on the CYCLE800's line; what the run cannot make
/// of a call is named on it; `CYCLE800()` takes the swivel back.
#[test]
fn a_swivel_is_held_to_the_rotary_axes_limits_and_taken_back() {
    let data = five_axis(
        "$TC_CARR23[1]=\"T\" $TC_CARR34[1]=\"HEAD\" $TC_CARR35[1]=\"C\" $TC_CARR36[1]=\"B\"\n\
$TC_CARR9[1]=1 $TC_CARR11[1]=1\n\
N36100 $MA_POS_LIMIT_MINUS[B]=-30\nN36110 $MA_POS_LIMIT_PLUS[B]=30\n\
$TC_DP1[1,1]=120\n$TC_DP3[1,1]=100\n",
    );
    let program = "T1 D1 M6\nG0 X0 Y0 Z0 B0 C0\nCYCLE800(0,\"HEAD\",0,57,0,0,0,0,45,0,0,0,0,1)\n\
CYCLE800(1,\"HEAD\",0,57,0,0,0,0,20,0,0,0,0,1)\nCYCLE800()\nG1 X10 Y0 Z0 F1000\nM30\n";
    let (report, ends) = dry_run_ends(&data, program);
    let found: Vec<(usize, &str, f64)> = (report.violations.iter())
        .map(|v| (v.line, v.axis.as_str(), v.value))
        .collect();
    assert_eq!(found.len(), 1, "{found:?}");
    assert_eq!((found[0].0, found[0].1), (3, "B"), "{found:?}");
    assert!((found[0].2.abs() - 45.0).abs() < 1e-9, "{found:?}");
    let retraction = report
        .unknown
        .iter()
        .find(|u| u.line == 4)
        .expect("the retraction named");
    assert!(retraction.why.contains("`_FR` 1"), "{}", retraction.why);
    // Taken back: X10 on the unswivelled plane, the tool along Z, the
    // rotary axes left where the last swivel put them.
    let (_, last) = ends.iter().find(|(line, _)| *line == 6).expect("line 6");
    let known = |k: usize| last[k].expect("known");
    assert!((known(0) - 10.0).abs() < 1e-9, "{last:?}");
    assert!(
        known(1).abs() < 1e-9 && (known(2) - 100.0).abs() < 1e-9,
        "{last:?}"
    );
    assert!((known(3).abs() - 20.0).abs() < 1e-9, "B stays: {last:?}");
}

type Points = Vec<[f64; 2]>;

/// The tool centre's path the textbook way, for a closed polygon under
/// G41/G42 (`side` +1 left, -1 right) with the radius `r`: each edge moved
/// along its normal; an inside corner, and under G451 an outside one, where
/// the moved edges meet (on the bisector); under G450 an outside corner is
/// a circle about the vertex. Returns each block's end (the approach, the
/// infeed, the edges, the retraction) and the path's points where its
/// extremes may lie (lines' ends, arcs sampled), or `None` where an edge is
/// too short for the radius.
fn centre_path(
    vertices: &[[f64; 2]],
    side: f64,
    r: f64,
    circles: bool,
    from: [f64; 2],
    to: [f64; 2],
) -> Option<(Points, Points)> {
    let n = vertices.len();
    // The edges v0 v1 .. v(n-1) v0, and v0 v1 again to end on a corner.
    let edges: Vec<([f64; 2], [f64; 2])> = (0..=n)
        .map(|k| (vertices[k % n], vertices[(k + 1) % n]))
        .collect();
    let unit = |(a, b): ([f64; 2], [f64; 2])| {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let length = dx.hypot(dy);
        [dx / length, dy / length]
    };
    // The offset of an edge: the radius to its left, or right.
    let offset = |e| {
        let t = unit(e);
        [-t[1] * side * r, t[0] * side * r]
    };
    let add = |p: [f64; 2], o: [f64; 2]| [p[0] + o[0], p[1] + o[1]];
    let mut ends = vec![add(edges[0].0, offset(edges[0]))];
    ends.push(ends[0]);
    let mut points = vec![from, ends[0]];
    let mut start = ends[0];
    for k in 0..=n {
        let (o, t) = (offset(edges[k]), unit(edges[k]));
        let vertex = edges[k].1;
        let (end, next_start) = if k == n {
            let end = add(vertex, o);
            (end, end)
        } else {
            let (p, q) = (offset(edges[k + 1]), unit(edges[k + 1]));
            let turn = t[0] * q[1] - t[1] * q[0];
            let inside = side * turn > 0.0;
            if inside || !circles {
                let cos = (o[0] * p[0] + o[1] * p[1]) / (r * r);
                let meet = add(
                    vertex,
                    [(o[0] + p[0]) / (1.0 + cos), (o[1] + p[1]) / (1.0 + cos)],
                );
                (meet, meet)
            } else {
                let (a, b) = (o[1].atan2(o[0]), p[1].atan2(p[0]));
                let mut sweep = b - a;
                if sweep > std::f64::consts::PI {
                    sweep -= std::f64::consts::TAU;
                }
                if sweep < -std::f64::consts::PI {
                    sweep += std::f64::consts::TAU;
                }
                for i in 0..=20_000 {
                    let angle = a + sweep * f64::from(i) / 20_000.0;
                    points.push(add(vertex, [r * angle.cos(), r * angle.sin()]));
                }
                (add(vertex, o), add(vertex, p))
            }
        };
        // The moved edge must keep its direction: else the tool does not fit.
        if (end[0] - start[0]) * t[0] + (end[1] - start[1]) * t[1] <= 0.0 {
            return None;
        }
        points.push(end);
        ends.push(end);
        start = next_start;
    }
    ends.push(to);
    points.push(to);
    Some((ends, points))
}

/// G41/G42 on random convex polygons, left and right, inside and outside,
/// G450 and G451: each block's end to 1e-9 against [`centre_path`], a move
/// off the plane run where the approach ends, and the limits 1 µm inside
/// the path's extremes reported, 1 µm outside not.
#[test]
fn radius_compensation_puts_the_centre_beside_the_contour() {
    let mut numbers = Numbers(45);
    let mut checked = 0;
    for case in 0..40 {
        let n = 3 + case % 4;
        let (cx, cy, big) = (
            numbers.between(200.0, 300.0),
            numbers.between(150.0, 250.0),
            numbers.between(50.0, 90.0),
        );
        let ccw = numbers.next() < 0.5;
        let vertices: Vec<[f64; 2]> = (0..n)
            .map(|k| {
                let step = std::f64::consts::TAU / n as f64;
                let angle = step * k as f64 + numbers.between(-0.25, 0.25) * step;
                let angle = if ccw { angle } else { -angle };
                let radius = big * numbers.between(0.85, 1.0);
                [
                    format!("{:.4}", cx + radius * angle.cos())
                        .parse()
                        .expect("x"),
                    format!("{:.4}", cy + radius * angle.sin())
                        .parse()
                        .expect("y"),
                ]
            })
            .collect();
        let side = if numbers.next() < 0.5 { 1.0 } else { -1.0 };
        let r = numbers.between(1.0, 8.0);
        let circles = numbers.next() < 0.5;
        let (from, to) = ([cx + 2.0 * big, cy], [cx + 2.0 * big, cy + 10.0]);
        let Some((ends, points)) = centre_path(&vertices, side, r, circles, from, to) else {
            continue;
        };
        checked += 1;
        let mut program = format!(
            "T1 M6\nD1\nG0 G90 X{} Y{} Z0\nG1 {} {} F1000 X{} Y{}\nZ-5\n",
            from[0],
            from[1],
            if side > 0.0 { "G41" } else { "G42" },
            if circles { "G450" } else { "G451" },
            vertices[0][0],
            vertices[0][1]
        );
        for k in 0..=n {
            let v = vertices[(k + 1) % n];
            program.push_str(&format!("X{} Y{}\n", v[0], v[1]));
        }
        program.push_str(&format!("G40 X{} Y{}\nM30\n", to[0], to[1]));
        let tool = format!("$TC_DP1[1,1]=120\n$TC_DP6[1,1]={r}\n");
        let (report, at) = dry_run_ends(&machine(&tool), &program);
        let unknown: Vec<_> = (report.unknown.iter())
            .filter(|u| {
                !(u.why.starts_with("where the axes were before")
                    || u.why.starts_with("MD20210")
                    || u.why.starts_with("MD20230"))
            })
            .collect();
        assert!(unknown.is_empty(), "case {case}: {unknown:?}\n{program}");
        // Blocks from the approach (line 4) to the retraction, in order.
        let lines: Vec<usize> = at.iter().map(|(line, _)| *line).collect();
        assert_eq!(lines, (1..=program.lines().count()).collect::<Vec<_>>());
        for (k, end) in ends.iter().enumerate() {
            let (line, mcs) = &at[3 + k];
            for (axis, want) in end.iter().enumerate() {
                let got = mcs[axis].expect("position");
                assert!(
                    (got - want).abs() < 1e-9,
                    "case {case}, line {line}, axis {axis}: {got} != {want}\n{program}"
                );
            }
        }
        assert_eq!(at[4].1[2], Some(-5.0), "the infeed's Z");
        for axis in 0..2 {
            let values = points.iter().map(|p| p[axis]);
            let high = values.clone().fold(f64::MIN, f64::max);
            let low = values.fold(f64::MAX, f64::min);
            for (side, limit, beyond, datum) in [
                (Side::Plus, high - 1e-6, true, "N36110 $MA_POS_LIMIT_PLUS"),
                (Side::Plus, high + 1e-6, false, "N36110 $MA_POS_LIMIT_PLUS"),
                (Side::Minus, low + 1e-6, true, "N36100 $MA_POS_LIMIT_MINUS"),
                (Side::Minus, low - 1e-6, false, "N36100 $MA_POS_LIMIT_MINUS"),
            ] {
                let limited = format!("{tool}{datum}[AX{}]={limit}\n", axis + 1);
                let report = dry_run(&machine(&limited), &program);
                let found = (report.violations.iter())
                    .any(|v| v.side == side && v.axis == ["X1", "Y1"][axis]);
                assert_eq!(
                    found, beyond,
                    "case {case}, axis {axis}, {side:?} limit {limit}: {:?}\n{program}",
                    report.violations
                );
            }
        }
    }
    assert!(
        checked >= 30,
        "only {checked} of 40 polygons fit their tool"
    );
}

/// Arcs under G41/G42: a slot's outline (two lines, two half circles, all
/// tangent) run both ways round, the tool inside and outside: the centre
/// goes round the same slot grown or shrunk by the radius, whose ends and
/// extremes are known in closed form.
#[test]
fn radius_compensation_follows_arcs_at_their_radius_grown_or_shrunk() {
    let (cx, cy, half, radius, r) = (300.0, 200.0, 40.0, 25.0, 6.0);
    for ccw in [true, false] {
        for side in [1.0, -1.0] {
            // Round the slot counter-clockwise the tool's left is inside.
            let inside = (side > 0.0) == ccw;
            let grown = if inside { radius - r } else { radius + r };
            let y = |s: f64| if ccw { s } else { -s };
            let arc = if ccw { "G3" } else { "G2" };
            let program = format!(
                "T1 M6\nD1\nG0 G90 X{x0} Y{ya} Z0\nG1 {g} F1000 X{x0} Y{yb}\nX{x1} Y{yb}\n\
{arc} X{x1} Y{yc} CR={radius}\nG1 X{x0} Y{yc}\n{arc} X{x0} Y{yb} CR={radius}\nG1 X{x1} Y{yb}\n\
G40 X{x1} Y{ya}\nM30\n",
                x0 = cx - half,
                x1 = cx + half,
                ya = cy + y(-2.0 * radius),
                yb = cy + y(-radius),
                yc = cy + y(radius),
                g = if side > 0.0 { "G41" } else { "G42" },
            );
            let tool = format!("$TC_DP1[1,1]=120\n$TC_DP6[1,1]={r}\n");
            let (report, at) = dry_run_ends(&machine(&tool), &program);
            let unknown: Vec<_> = (report.unknown.iter())
                .filter(|u| !u.why.starts_with("where the axes were before"))
                .collect();
            assert!(unknown.is_empty(), "{unknown:?}\n{program}");
            let expected = [
                (4, cx - half, cy + y(-grown)),
                (5, cx + half, cy + y(-grown)),
                (6, cx + half, cy + y(grown)),
                (7, cx - half, cy + y(grown)),
                (8, cx - half, cy + y(-grown)),
                (9, cx + half, cy + y(-grown)),
                (10, cx + half, cy + y(-2.0 * radius)),
            ];
            for (line, x, y) in expected {
                let mcs = &at[line - 1].1;
                assert_near(
                    mcs[0].expect("x"),
                    x,
                    1e-9,
                    &format!("line {line} X\n{program}"),
                );
                assert_near(
                    mcs[1].expect("y"),
                    y,
                    1e-9,
                    &format!("line {line} Y\n{program}"),
                );
            }
            let travel = |k: usize| (report.axes[k].min, report.axes[k].max);
            assert_eq!(travel(0).1, Some(cx + half + grown), "{program}");
            assert_eq!(travel(0).0, Some(cx - half - grown), "{program}");
            let ys = [cy - grown, cy + grown, cy + y(-2.0 * radius)];
            let lowest = ys.iter().copied().fold(f64::MAX, f64::min);
            let highest = ys.iter().copied().fold(f64::MIN, f64::max);
            assert_near(travel(1).0.expect("y min"), lowest, 1e-9, "Y min");
            assert_near(travel(1).1.expect("y max"), highest, 1e-9, "Y max");
        }
    }
}

/// MD20210 and MD20230 as the data give them: under G451 a corner more
/// pointed than MD20210 gets a circle after all; under G450 one flatter
/// than MD20230 gets the meeting point. Without them the run says so.
#[test]
fn corners_switch_as_the_machine_data_say() {
    // Along +X, then back at 135 degrees (pointed), then a 20 degree bend.
    let program = "T1 M6\nD1\nG0 G90 X0 Y-50 Z0\nG1 G42 G451 F1000 X0 Y0\nX100\n\
X29.2893 Y70.7107\nX-70.7107 Y107.1075\nG40 X-70 Y150\nM30\n";
    let tool = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=5\n";
    let limits = "N20210 $MC_CUTCOM_CORNER_LIMIT=100\nN20230 $MC_CUTCOM_CURVE_INSERT_LIMIT=30\n";
    let end_of = |at: &Ends, line: usize| [at[line - 1].1[0], at[line - 1].1[1]];
    // The data's limits: the pointed corner (line 5 to 6) gets its circle,
    // line 5 ends square to its end.
    let (report, at) = dry_run_ends(&machine(&format!("{tool}{limits}")), program);
    assert!(
        report.unknown.iter().all(|u| !u.why.starts_with("MD202")),
        "{:?}",
        report.unknown
    );
    assert_eq!(end_of(&at, 5), [Some(100.0), Some(-5.0)]);
    // Without them: the meeting point, and the run says why.
    let (report, at) = dry_run_ends(&machine(tool), program);
    assert!(
        report.unknown.iter().any(|u| u.why.starts_with("MD20210")),
        "{:?}",
        report.unknown
    );
    let x = end_of(&at, 5)[0].expect("x");
    assert!(x > 105.0, "the meeting point lies past the corner: {x}");
    // G450 at the 20 degree bend (line 6 to 7): the data say meet, not circle.
    let program = program.replace("G451", "G450");
    let (_, at) = dry_run_ends(&machine(&format!("{tool}{limits}")), &program);
    let [x, y] = end_of(&at, 6).map(|v| v.expect("position"));
    let half = std::f64::consts::FRAC_1_SQRT_2;
    let on_normal = [29.2893 - 5.0 * half, 70.7107 - 5.0 * half];
    assert!(
        (x - on_normal[0]).hypot(y - on_normal[1]) > 0.05,
        "meets beyond the square end: {x} {y}"
    );
}

/// ROTS and AROTS turn the frame by solid angles: one angle is ROT about
/// its axis (Programming Manual, "ROTS, AROTS, CROTS"); two angles keep
/// the new X in the old ZX plane; AROTS adds to what is there.
#[test]
fn solid_angles_turn_the_frame() {
    let ends = |program: &str| {
        let (report, at) = dry_run_ends(&machine(""), program);
        let unknown: Vec<_> = (report.unknown.iter())
            .filter(|u| !u.why.starts_with("where the axes were before"))
            .collect();
        assert!(unknown.is_empty(), "{unknown:?}");
        at.last().map(|(_, mcs)| mcs.clone()).unwrap_or_default()
    };
    let rot = ends("ROT Y30\nG0 X10 Y20 Z30\n");
    let rots = ends("ROTS Y30\nG0 X10 Y20 Z30\n");
    for (a, b) in rot.iter().zip(&rots) {
        assert_near(
            a.expect("ROT"),
            b.expect("ROTS"),
            1e-12,
            "ROTS Y30 = ROT Y30",
        );
    }
    // ROTS X Y: the new X axis lies in the old ZX plane, turned by Y's angle.
    let x = ends("ROTS X20 Y30\nG0 X1 Y0 Z0\n");
    let y30 = 30f64.to_radians();
    assert_near(x[1].expect("y"), 0.0, 1e-12, "new X in the ZX plane");
    assert_near(x[0].expect("x"), y30.cos(), 1e-12, "new X");
    assert_near(x[2].expect("z"), -y30.sin(), 1e-12, "new X");
    // AROTS after TRANS: the shift stays, the turn is added.
    let added = ends("TRANS X100\nAROTS Z90\nG0 X10 Y0 Z0\n");
    assert_near(added[0].expect("x"), 100.0, 1e-12, "AROTS keeps TRANS");
    assert_near(added[1].expect("y"), 10.0, 1e-12, "AROTS turns");
}

/// MD20150 `$MC_GCODE_RESET_VALUES`: the G functions the program starts
/// with where the data hold them (G1 and G54 here), else the control's.
#[test]
fn the_program_starts_in_the_g_functions_of_md20150() {
    let program = "G90 X10 Y-10 Z-10 F100\nX110\n";
    let frames = "$P_UIFR[1,X,TR]=100\n";
    let reset = "N20150 $MC_GCODE_RESET_VALUES[0]=2\nN20150 $MC_GCODE_RESET_VALUES[7]=2\n";
    let (report, at) = dry_run_ends(&machine(&format!("{frames}{reset}")), program);
    assert_eq!(at[1].1[0], Some(210.0), "G54 active from the start");
    // G1 at F100: 100 mm take a minute, and more with the ramps.
    assert!(report.time_s >= 60.0, "{}", report.time_s);
    assert!(
        report.assumptions[0].contains("G1 G54 (MD20150)"),
        "{:?}",
        report.assumptions
    );
    let (report, at) = dry_run_ends(&machine(frames), program);
    assert_eq!(at[1].1[0], Some(110.0), "no frame at the start");
    assert!(report.time_s < 1.0, "G0: {}", report.time_s);
    assert!(
        report.assumptions[0].contains("hold no MD20150 for them"),
        "{:?}",
        report.assumptions
    );
}

/// A parameter the call leaves out is passed as 0 where it is a number
/// by value (Programming Manual, "Subprogram call": incomplete parameter
/// transfer); a STRING left out stays unknown.
#[test]
fn a_parameter_left_out_is_passed_as_zero() {
    let dir = scratch("run_omitted");
    std::fs::write(dir.join("MACHINE.INI"), machine("")).expect("write");
    std::fs::write(
        dir.join("MAIN.MPF"),
        "G0 X5 Y5 Z5\nSUBP(,7)\nSUBP(3)\nNAMED()\nG0 Z0\nM30\n",
    )
    .expect("write");
    std::fs::write(
        dir.join("SUBP.SPF"),
        "PROC SUBP(INT _A, REAL _B)\nG0 X=_A Y=_B\nIF $P_SUBPAR[1] AND NOT $P_SUBPAR[2]\nG0 Z-3\nENDIF\nM17\n",
    )
    .expect("write");
    std::fs::write(
        dir.join("NAMED.SPF"),
        "PROC NAMED(STRING[8] _NAME, REAL _Z)\nG0 Z=_Z\nMSG(_NAME)\nM17\n",
    )
    .expect("write");
    let read = run_with_blocks(&dir);
    let blocks = read["blocks"].as_array().expect("blocks");
    let at = |x: f64, y: f64| {
        blocks
            .iter()
            .any(|b| b["line"] == 2 && b["mcs"]["X1"] == x && b["mcs"]["Y1"] == y)
    };
    assert!(at(0.0, 7.0) && at(3.0, 0.0), "{blocks:?}");
    // `$P_SUBPAR`: only SUBP(3) gives the first and not the second.
    assert_eq!(read["axes"]["Z1"]["min"], -3.0, "{read}");
    let unknown = read["unknown"].to_string();
    assert!(!unknown.contains("SUBPAR"), "{unknown}");
    assert!(
        !unknown.contains("_A") && !unknown.contains("_B") && !unknown.contains("_Z"),
        "{unknown}"
    );
}

/// A subprogram with SAVE gives back the caller's G functions and
/// programmable frame on its return; one without keeps what it set.
#[test]
fn a_subprogram_with_save_gives_back_the_callers_modes() {
    let dir = scratch("run_save");
    std::fs::write(
        dir.join("MACHINE.INI"),
        machine("N10240 $MN_SCALING_SYSTEM_IS_METRIC=1\n"),
    )
    .expect("write");
    std::fs::write(
        dir.join("MAIN.MPF"),
        "G700 G0 X0 Y0 Z0\nSUBS\nG0 X10\nSUBN\nG0 X10\nM30\n",
    )
    .expect("write");
    std::fs::write(
        dir.join("SUBS.SPF"),
        "PROC SUBS SAVE\nG710 G91\nTRANS X5\nG0 Y1\nM17\n",
    )
    .expect("write");
    std::fs::write(dir.join("SUBN.SPF"), "PROC SUBN\nG710\nTRANS X5\nM17\n").expect("write");
    let read = run_with_blocks(&dir);
    let blocks = read["blocks"].as_array().expect("blocks");
    let x_at = |line: usize| -> Vec<f64> {
        (blocks.iter())
            .filter(|b| b["line"] == line && b["program"].is_null())
            .filter_map(|b| b["mcs"]["X1"].as_f64())
            .collect()
    };
    // After SUBS: inch, absolute, no TRANS again (254 mm); after SUBN:
    // millimetres and its TRANS (15 mm).
    assert_eq!(x_at(3), [254.0], "{blocks:?}");
    assert_eq!(x_at(5), [15.0], "{blocks:?}");
}

/// The values an archive holds for GUD variables and R parameters (the
/// control's state when it was written) are read, below what the user
/// sets, and said among the assumptions.
#[test]
fn the_machines_gud_values_and_r_parameters_are_read() {
    let dir = scratch("run_gud_values");
    std::fs::write(
        dir.join("MACHINE.INI"),
        machine("_DM_SIZE=1.5\nR[100]=20 '1a2b\n_TABLE[2]=7\n"),
    )
    .expect("write");
    std::fs::write(
        dir.join("MAIN.MPF"),
        "G0 X=R100*_DM_SIZE Y=_TABLE[2] Z0\nM30\n",
    )
    .expect("write");
    let read = run_with_blocks(&dir);
    assert_eq!(read["axes"]["X1"]["max"], 30.0, "{read}");
    assert_eq!(read["axes"]["Y1"]["max"], 7.0, "{read}");
    let assumed = read["assumptions"].to_string();
    assert!(
        assumed.contains("3 values of GUD variables and R parameters"),
        "{assumed}"
    );
}

/// Where compensation cannot go on, the element held back ends square and
/// the next block starts there: a move to a position unknown offline, a
/// move under G53; a slot narrower than the tool is a bottleneck, named;
/// G451 past a small arc, where the extended elements never meet, takes
/// the circle.
#[test]
fn radius_compensation_ends_an_element_where_the_control_would() {
    let tool = |r: f64| format!("$TC_DP1[1,1]=120\n$TC_DP6[1,1]={r}\n");
    let head = "T1 M6\nD1\nG0 X0 Y-20 Z0\nG41 G1 X0 Y0 F500\n";
    // The element to X20 Y20 ends square (X 16.46, Y 23.54); the move to
    // an unknown X starts there, Y kept.
    let (_, at) = dry_run_ends(
        &machine(&tool(5.0)),
        &format!("{head}X20 Y20\nX=R99\nM30\n"),
    );
    let half = 5.0 * std::f64::consts::FRAC_1_SQRT_2;
    assert_near(
        at[4].1[1].expect("y"),
        20.0 + half,
        1e-9,
        "the element's square end",
    );
    assert_near(
        at[5].1[1].expect("y"),
        20.0 + half,
        1e-9,
        "Y kept by the next move",
    );
    // A G53 move of Z alone: where Z goes is the same with and without G41.
    let retract = |g: &str| {
        let program =
            format!("T1 M6\nD1\nG0 X0 Y-20 Z0\n{g} G1 X0 Y0 F500\nX50\nG53 G0 Z-10\nG1 Y40\nM30\n");
        let (_, at) = dry_run_ends(&machine(&tool(5.0)), &program);
        at[5].1[2]
    };
    assert_eq!(retract("G41"), retract("G40"));
    // Inside a slot 8 wide a tool of 10 does not fit between its corners.
    let slot =
        format!("{head}Y10\nY0\nX8\nY10\nG40 X20\nM30\n").replace("G0 X0 Y-20", "G0 X-20 Y10");
    let (report, _) = dry_run_ends(&machine(&tool(5.0)), &slot);
    assert!(
        report
            .unknown
            .iter()
            .any(|u| u.why.contains("does not fit the inside corner")),
        "{:?}",
        report.unknown
    );
    // G451 past a small arc: the circle, no bottleneck.
    let small = "T1 M6\nD1\nG0 X30 Y-20 Z0\nG41 G451 G1 X20 Y0 F500\nX10\nG3 X0 Y10 I-10 J0\nG1 Y20\nG40 X-20\nM30\n";
    let (report, _) = dry_run_ends(&machine(&tool(6.0)), small);
    assert!(
        report
            .unknown
            .iter()
            .all(|u| !u.why.contains("does not fit")),
        "{:?}",
        report.unknown
    );
}
