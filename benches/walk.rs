//! The CYCLE600 walk on the shapes that once made it slow: loops nested
//! deep, each writing a variable of its own; many IFs with unknown
//! conditions over many variables; a CYCLE600 inside all of them; 100
//! loops around 100,000 blocks and 100,000 nested IFs (where the cost was
//! lines times depth). `cargo bench --bench walk`; whole programs are
//! `throughput`'s job.

use divan::{black_box, Bencher};
use sinuprep::semantic::{analyze, Model, Supplied};

fn main() {
    divan::main();
}

const CALL: &str = "CYCLE600(0, \"UFK600\", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)\n";

/// `depth` loops (`open` with `{i}` for the level), each writing R1000+i.
fn nested(open: &str, close: &str, depth: usize) -> String {
    let mut program = String::new();
    for i in 0..depth {
        program.push_str(&open.replace("{i}", &i.to_string()));
        program.push_str(&format!("\nR{n}=R{n}+1\n", n = 1000 + i));
    }
    program.push_str(CALL);
    for _ in 0..depth {
        program.push_str(close);
        program.push('\n');
    }
    program.push_str("M30\n");
    program
}

#[divan::bench(args = [100, 400, 2000])]
fn nested_for_loops(bencher: Bencher, depth: usize) {
    let program = nested("FOR R{i}=0 TO 2", "ENDFOR", depth);
    bencher.bench(|| {
        let model = Model::of(black_box(program.as_bytes()));
        analyze(&model, &Supplied::default(), None)
    });
}

#[divan::bench(args = [100, 400, 2000])]
fn nested_while_loops(bencher: Bencher, depth: usize) {
    let program = nested("WHILE R{i}<3", "ENDWHILE", depth);
    bencher.bench(|| {
        let model = Model::of(black_box(program.as_bytes()));
        analyze(&model, &Supplied::default(), None)
    });
}

/// `count` DEF variables, then `count` IFs with unknown conditions, each
/// writing one of them.
#[divan::bench(args = [1000, 5000])]
fn unknown_ifs_over_many_variables(bencher: Bencher, count: usize) {
    let mut program = String::new();
    for i in 0..count {
        program.push_str(&format!("DEF REAL V{i}\n"));
    }
    for i in 0..count {
        program.push_str(&format!("IF R{i}>0\nV{i}=V{i}+1\nENDIF\n"));
    }
    program.push_str(CALL);
    program.push_str("M30\n");
    bencher.bench(|| {
        let model = Model::of(black_box(program.as_bytes()));
        analyze(&model, &Supplied::default(), None)
    });
}

/// 100 nested FOR loops around `lines` blocks, each reading and writing one
/// of 100 R parameters (100,000 lines: 0.9 MB).
#[divan::bench(args = [100_000])]
fn hundred_loops_around_many_lines(bencher: Bencher, lines: usize) {
    let mut program = String::new();
    for i in 0..100 {
        program.push_str(&format!("FOR R{i}=0 TO 2\n"));
    }
    for j in 0..lines {
        program.push_str(&format!("R{n}=R{n}+1\n", n = 1000 + j % 100));
    }
    program.push_str(CALL);
    for _ in 0..100 {
        program.push_str("ENDFOR\n");
    }
    program.push_str("M30\n");
    bencher.bench(|| {
        let model = Model::of(black_box(program.as_bytes()));
        analyze(&model, &Supplied::default(), None)
    });
}

/// `depth` nested IFs with unknown conditions, each writing an R parameter,
/// a CYCLE600 inside all of them (deeper than the walk follows: C618).
#[divan::bench(args = [100_000])]
fn nested_unknown_ifs(bencher: Bencher, depth: usize) {
    let mut program = String::new();
    for i in 0..depth {
        program.push_str(&format!("IF R{}>0\nR{}=1\n", i % 100, 100 + i % 100));
    }
    program.push_str(CALL);
    for _ in 0..depth {
        program.push_str("ENDIF\n");
    }
    program.push_str("M30\n");
    bencher.bench(|| {
        let model = Model::of(black_box(program.as_bytes()));
        analyze(&model, &Supplied::default(), None)
    });
}

/// A hand-written program of `pockets` sections (DEF variables, WHILE, IF
/// with unknown conditions, jumps back): the walk alone, the walk that also
/// finds one variable's value at each of its uses (what an editor's hover
/// on `_Z` reads), and every variable's.
fn pockets(pockets: usize) -> String {
    let mut program = String::from("DEF REAL _DEPTH=5, _STEP=0.5, _Z\nDEF INT _COUNT=0\n");
    for section in 0..pockets {
        program.push_str(&format!(
            "POCKET{section}:\n_Z=0\nWHILE _Z>-_DEPTH\n_Z=_Z-_STEP\nIF R{r}>_Z*2\n\
             G1 X=R{r}+10 Y=R{r}*0.5 Z=_Z F800\nELSE\nG1 X=10 Y20 Z=_Z F400\nENDIF\n\
             ENDWHILE\n_COUNT=_COUNT+1\nIF _COUNT<3 GOTOB POCKET{section}\n",
            r = section % 99 + 1,
        ));
    }
    program.push_str("M30\n");
    program
}

#[divan::bench(args = ["none", "_Z", "every"])]
fn values_at_uses_in_800_pockets(bencher: Bencher, looked_at: &str) {
    use sinuprep::semantic::uses::{Namespace, Role, Uses};
    use sinuprep::semantic::walk::{values_at, Probe};
    let program = pockets(800);
    let model = Model::of(program.as_bytes());
    let uses = Uses::of(&model);
    let probes: Vec<Probe> = uses
        .all()
        .iter()
        .filter(|u| u.namespace == Namespace::Variable)
        .filter(|u| looked_at == "every" || u.name == looked_at)
        .map(|u| Probe {
            row: u.row,
            name: u.span,
            after: matches!(u.role, Role::Writes | Role::Defines),
        })
        .collect();
    bencher.bench(|| values_at(&model, &Supplied::default(), None, black_box(&probes), None));
}
