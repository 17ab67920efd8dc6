//! The dry run as a page a person looks at rather than reads: one
//! self-contained HTML file (inline SVG, no script, nothing fetched) with
//! each machine axis's position over time against its limits, the path seen
//! from above and from the front, and the time per tool. The run's blocks
//! are kept as they pass ([`Trace::record`]), thinned to at most
//! [`MOST_POINTS`] so that a program of millions of blocks draws in a page.

use std::fmt::Write;

use crate::run::{BlockEnd, Report, Setup};

/// At most this many block ends are drawn (one in every 2^k kept).
pub const MOST_POINTS: usize = 20_000;

/// A point of the path: a block's end, or one along its arc (drawn in the
/// views, not over time).
struct Point {
    t: f64,
    mcs: Vec<Option<f64>>,
    on_arc: bool,
}

/// The block ends kept for drawing: time and each run axis's machine position.
pub struct Trace {
    names: Vec<String>,
    limits: Vec<[Option<f64>; 2]>,
    /// The geometry axes' places among the run axes (X, Y, Z).
    geometry: [Option<usize>; 3],
    points: Vec<Point>,
    /// One block end in this many is kept.
    every: u64,
    seen: u64,
}

impl Trace {
    pub fn new(setup: &Setup, second_limits: bool) -> Trace {
        let mut geometry = [None; 3];
        for (k, axis) in setup.axes.iter().enumerate() {
            if let Some(g) = axis.geometry {
                geometry[g] = Some(k);
            }
        }
        Trace {
            names: setup.axes.iter().map(|a| a.machine_name()).collect(),
            limits: setup.axes.iter().map(|a| a.limits(second_limits)).collect(),
            geometry,
            points: Vec::new(),
            every: 1,
            seen: 0,
        }
    }

    /// Keeps `end` if it falls on the current stride; past [`MOST_POINTS`],
    /// every other point kept is dropped and the stride doubles.
    pub fn record(&mut self, end: &BlockEnd) {
        self.seen += 1;
        if !(self.seen - 1).is_multiple_of(self.every) {
            return;
        }
        // An arc drawn as the path it is: points along it every 5°.
        if let Some(arc) = end.arc {
            let steps = (arc.sweep / 5f64.to_radians()).ceil().max(1.0) as usize;
            for i in 1..steps {
                let p = arc.point(arc.sweep * i as f64 / steps as f64);
                let mut mcs = end.mcs.to_vec();
                for (g, k) in self.geometry.iter().enumerate() {
                    if let Some(k) = k {
                        mcs[*k] = Some(p[g]);
                    }
                }
                self.points.push(Point {
                    t: end.t_s,
                    mcs,
                    on_arc: true,
                });
            }
        }
        self.points.push(Point {
            t: end.t_s,
            mcs: end.mcs.to_vec(),
            on_arc: false,
        });
        if self.points.len() >= MOST_POINTS {
            let mut keep = false;
            self.points.retain(|_| {
                keep = !keep;
                keep
            });
            self.every *= 2;
        }
    }
}

const WIDTH: f64 = 860.0;
const HEIGHT: f64 = 220.0;
const MARGIN: f64 = 48.0;

/// The page: a summary, then the plots.
pub fn html(trace: &Trace, report: &Report, title: &str) -> String {
    let mut page = String::new();
    let _ = write!(
        page,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{}</title>\n<style>\
body{{font:14px system-ui,sans-serif;margin:24px;color:#222}}h1{{font-size:20px}}h2{{font-size:16px;margin-top:28px}}\
svg{{background:#fafafa;border:1px solid #ddd}}.limit{{stroke:#c00;stroke-dasharray:6 4}}\
.path{{fill:none;stroke:#1f5fa8;stroke-width:1.2}}.axis{{stroke:#888}}text{{font-size:11px;fill:#444}}\
.bar{{fill:#1f5fa8}}.bad{{color:#c00}}</style></head><body>\n",
        escape(title)
    );
    let _ = write!(page, "<h1>{}</h1>\n<p>", escape(title));
    let upper = report.time_bounds_s[1];
    let _ = write!(
        page,
        "Time {} (at least {}, at most {}); {} blocks run",
        seconds(report.time_s),
        seconds(report.time_bounds_s[0]),
        if upper.is_finite() {
            seconds(upper)
        } else {
            "?".to_string()
        },
        report.blocks
    );
    let violations = report.violations.len() as u64 + report.violations_untold;
    if violations > 0 {
        let _ = write!(
            page,
            "; <span class=\"bad\">{}</span>",
            count(
                violations,
                "excursion past a software limit",
                "excursions past a software limit"
            )
        );
    }
    if !report.unknown.is_empty() {
        let unknown = report.unknown.len() as u64;
        let _ = write!(
            page,
            "; {} (listed by the command)",
            count(unknown, "thing unknown offline", "things unknown offline")
        );
    }
    if trace.every > 1 {
        let _ = write!(page, " (one block end in {} drawn)", trace.every);
    }
    if let Some(endless) = &report.endless {
        let _ = write!(
            page,
            "; endless: from line {} it repeats every {} until it is stopped (drawn until the repetition was found)",
            endless.line,
            seconds(endless.pass_s)
        );
    }
    page.push_str("</p>\n");
    page.push_str("<h2>Machine axes over time</h2>\n");
    for k in 0..trace.names.len() {
        let points: Vec<(f64, f64)> = trace
            .points
            .iter()
            .filter(|p| !p.on_arc)
            .filter_map(|p| Some((p.t, p.mcs[k]?)))
            .collect();
        if points.is_empty() {
            continue;
        }
        let limits: Vec<f64> = trace.limits[k].iter().flatten().copied().collect();
        let name = format!("{} over time (s)", trace.names[k]);
        plot(&mut page, &name, &points, &limits, &[], false);
    }
    let [x, y, z] = trace.geometry;
    for (name, first, second) in [("From above (X, Y)", x, y), ("From the front (X, Z)", x, z)] {
        let (Some(a), Some(b)) = (first, second) else {
            continue;
        };
        let points: Vec<(f64, f64)> = trace
            .points
            .iter()
            .filter_map(|p| Some((p.mcs[a]?, p.mcs[b]?)))
            .collect();
        if points.is_empty() {
            continue;
        }
        let verticals: Vec<f64> = trace.limits[a].iter().flatten().copied().collect();
        let limits: Vec<f64> = trace.limits[b].iter().flatten().copied().collect();
        page.push_str(&format!("<h2>{name}</h2>\n"));
        let name = format!("{} over {}", trace.names[b], trace.names[a]);
        plot(&mut page, &name, &points, &limits, &verticals, true);
    }
    if !report.tools.is_empty() {
        page.push_str("<h2>Time per tool</h2>\n");
        let most = report.tools.iter().map(|t| t.time_s).fold(0.0, f64::max);
        let height = 24.0 * report.tools.len() as f64 + 8.0;
        let _ = writeln!(
            page,
            "<svg width=\"{WIDTH}\" height=\"{height}\" role=\"img\">"
        );
        for (i, tool) in report.tools.iter().enumerate() {
            let top = 8.0 + 24.0 * i as f64;
            let width = if most > 0.0 {
                (WIDTH - 260.0) * tool.time_s / most
            } else {
                0.0
            };
            let _ = writeln!(
                page,
                "<text x=\"8\" y=\"{}\">{}</text><rect class=\"bar\" x=\"80\" y=\"{top}\" width=\"{width:.1}\" height=\"16\"/>\
<text x=\"{:.1}\" y=\"{}\">{}</text>",
                top + 12.0,
                match tool.t.as_str() {
                    "none" => "no tool".to_string(),
                    number => format!("T{}", escape(number)),
                },
                86.0 + width,
                top + 12.0,
                seconds(tool.time_s)
            );
        }
        page.push_str("</svg>\n");
    }
    page.push_str("</body></html>\n");
    page
}

/// One plot of `points` (x, y) with horizontal lines at `limits` (y) and
/// vertical ones at `verticals` (x), both drawn within the plot's range;
/// `equal`: a millimetre as long across as up (a view of the path).
fn plot(
    page: &mut String,
    name: &str,
    points: &[(f64, f64)],
    limits: &[f64],
    verticals: &[f64],
    equal: bool,
) {
    let range = |values: &mut dyn Iterator<Item = f64>| {
        let (low, high) = values.fold((f64::MAX, f64::MIN), |(l, h), v| (l.min(v), h.max(v)));
        if high - low < 1e-9 {
            (low - 1.0, high + 1.0)
        } else {
            let pad = (high - low) * 0.05;
            (low - pad, high + pad)
        }
    };
    // The limits widen the range only as far as they are near the path:
    // a limit kilometres off flattens the plot to nothing.
    let (x_low, x_high) = range(&mut points.iter().map(|p| p.0));
    let (y_low, y_high) = range(&mut points.iter().map(|p| p.1));
    let near = |v: f64, low: f64, high: f64| v >= low - (high - low) && v <= high + (high - low);
    let (x_low, x_high) = range(
        &mut [x_low, x_high].into_iter().chain(
            verticals
                .iter()
                .copied()
                .filter(|v| near(*v, x_low, x_high)),
        ),
    );
    let (y_low, y_high) = range(
        &mut [y_low, y_high]
            .into_iter()
            .chain(limits.iter().copied().filter(|v| near(*v, y_low, y_high))),
    );
    // Time starts at 0, not before.
    let x_low = if points.iter().all(|p| p.0 >= 0.0) {
        x_low.max(0.0)
    } else {
        x_low
    };
    let across = WIDTH - 2.0 * MARGIN;
    let height = if equal {
        (across * (y_high - y_low) / (x_high - x_low)).clamp(120.0, 640.0) + MARGIN
    } else {
        HEIGHT
    };
    // In a view, one scale for both, the smaller of the two.
    let (x_scale, y_scale) = {
        let x_scale = across / (x_high - x_low);
        let y_scale = (height - MARGIN) / (y_high - y_low);
        if equal {
            (x_scale.min(y_scale), x_scale.min(y_scale))
        } else {
            (x_scale, y_scale)
        }
    };
    let sx = |x: f64| MARGIN + (x - x_low) * x_scale;
    let sy = |y: f64| height - MARGIN / 2.0 - (y - y_low) * y_scale;
    let _ = writeln!(
        page,
        "<svg width=\"{WIDTH}\" height=\"{height:.0}\" role=\"img\" aria-label=\"{}\">",
        escape(name)
    );
    let _ = writeln!(page, "<text x=\"4\" y=\"14\">{}</text>", escape(name));
    for (value, at) in [(y_low, sy(y_low)), (y_high, sy(y_high))] {
        let _ = writeln!(
            page,
            "<text x=\"2\" y=\"{:.1}\">{}</text>",
            at,
            number(value)
        );
    }
    for (value, at) in [(x_low, sx(x_low)), (x_high, sx(x_high))] {
        let _ = writeln!(
            page,
            "<text x=\"{:.1}\" y=\"{}\">{}</text>",
            at,
            height - 4.0,
            number(value)
        );
    }
    for limit in limits.iter().filter(|v| (y_low..=y_high).contains(*v)) {
        let _ = writeln!(
            page,
            "<line class=\"limit\" x1=\"{MARGIN}\" x2=\"{}\" y1=\"{y:.1}\" y2=\"{y:.1}\"/>\
<text x=\"{}\" y=\"{:.1}\">limit {}</text>",
            WIDTH - MARGIN,
            WIDTH - MARGIN - 70.0,
            sy(*limit) - 3.0,
            number(*limit),
            y = sy(*limit)
        );
    }
    for limit in verticals.iter().filter(|v| (x_low..=x_high).contains(*v)) {
        let _ = writeln!(
            page,
            "<line class=\"limit\" y1=\"{}\" y2=\"{}\" x1=\"{x:.1}\" x2=\"{x:.1}\"/>\
<text x=\"{:.1}\" y=\"{}\">limit {}</text>",
            MARGIN / 2.0,
            height - MARGIN / 2.0,
            sx(*limit) + 3.0,
            MARGIN / 2.0 + 10.0,
            number(*limit),
            x = sx(*limit)
        );
    }
    let mut polyline = String::with_capacity(points.len() * 14);
    for (x, y) in points {
        let _ = write!(polyline, "{:.1},{:.1} ", sx(*x), sy(*y));
    }
    let _ = writeln!(
        page,
        "<polyline class=\"path\" points=\"{}\"/>\n</svg>",
        polyline.trim_end()
    );
}

fn count(n: u64, one: &str, many: &str) -> String {
    match n {
        1 => format!("1 {one}"),
        n => format!("{n} {many}"),
    }
}

fn number(value: f64) -> String {
    crate::number::format(value, 3)
}

fn seconds(s: f64) -> String {
    format!("{} s", number(s))
}

/// Text safe inside HTML.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::run::RunAxis;

    #[test]
    fn a_trace_thins_itself_and_the_page_holds_its_plots() {
        let setup = Setup {
            axes: ["X", "Y", "Z"]
                .iter()
                .enumerate()
                .map(|(g, name)| RunAxis {
                    name: name.to_string(),
                    geometry: Some(g),
                    machine: None,
                })
                .collect(),
            ..Setup::default()
        };
        let mut trace = Trace::new(&setup, false);
        for i in 0..(3 * MOST_POINTS) {
            let at = [Some(i as f64), Some(0.5 * i as f64), None];
            trace.record(&BlockEnd {
                program: None,
                line: i + 1,
                mcs: &at,
                t_s: i as f64,
                arc: None,
            });
        }
        assert!(trace.points.len() < MOST_POINTS && trace.points.len() >= MOST_POINTS / 2);
        assert_eq!(trace.every, 4);
        let page = html(&trace, &Report::default(), "P<1>.MPF");
        assert!(page.contains("<title>P&lt;1&gt;.MPF</title>"));
        // X and Y over time and from above; Z has no position, nor the front view.
        assert_eq!(page.matches("<polyline").count(), 3, "{page}");
        assert!(!page.contains("http"), "nothing fetched");
    }
}
