//! Chapter `locomotion-definition` (document section 1): an object locomotes when its
//! average velocity is strictly outside the convex hull of the media velocities.
//!
//! Physics and geometry checked: the sailing cases of the document through the CLI; the
//! exact hull test against an independent brute force in integer arithmetic (a point is
//! in the closed hull iff it lies in a closed triangle, on a segment or at a point of the
//! media, Caratheodory; it is on the boundary iff a line through it and another medium
//! leaves all media on one side) on random instances full of degeneracies (duplicates,
//! collinear media, points on edges) and on near-degenerate instances where the naive
//! floating-point orientation gets the sign wrong.

use crate::common;

use locomotion_workbook::physics::locomotion::{classify, hull, orient2d, Position, V2};
use serde_json::Value;

fn run(args: &[&str]) -> (i32, String, String) {
    common::run_with(
        &["locomotion-definition", "--quick", "--json", "--no-figures"],
        args,
    )
}

fn results(args: &[&str]) -> Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "stderr: {err}");
    let r: Value = serde_json::from_str(&out).unwrap();
    for c in r["claims"].as_array().unwrap() {
        assert_eq!(c["verdict"], "confirmed", "{c}");
    }
    r["results"].clone()
}

#[test]
fn cli_scenes_follow_the_documents_sailing_rules() {
    let r = results(&[]);
    let keys: Vec<&str> = r.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(keys, ["is_locomotion", "reason"]);
    // Default: reaching at (1, 3) m/s with wind (5, 0) over still water: outside the segment.
    assert_eq!(r["is_locomotion"], true);
    // (expected from the document's text: slower downwind / at wind speed = dragging).
    for (object, expected) in [
        ("3,0", false),
        ("5,0", false),
        ("0,0", false),
        ("7,0", true),
        ("-2,0", true),
        ("0,3", true),
    ] {
        let flag = format!("--object-velocity={object}");
        let r = results(&[&flag]);
        assert_eq!(r["is_locomotion"], expected, "{object}");
        let reason = r["reason"].as_str().unwrap();
        assert_eq!(reason.ends_with(": locomotion"), expected, "{reason}");
    }
    // One medium: any nonzero relative velocity; several media by repeating the flag.
    let one = results(&["--medium-velocity", "1,1", "--object-velocity", "1,1"]);
    assert_eq!(one["is_locomotion"], false);
    let one = results(&[
        "--medium-velocity",
        "1,1",
        "--object-velocity",
        "1,1.000000000000001",
    ]);
    assert_eq!(one["is_locomotion"], true);
    let tri = [
        "--medium-velocity",
        "0,0",
        "--medium-velocity",
        "4,0",
        "--medium-velocity",
        "0,4",
    ];
    for (object, expected) in [
        ("1,1", false),
        ("2,2", false),
        ("2,2.0000000000000004", true),
    ] {
        let mut args = tri.to_vec();
        args.extend(["--object-velocity", object]);
        assert_eq!(results(&args)["is_locomotion"], expected, "{object}");
    }
}

/// Integer orientation sign (exact for |coordinates| < 2^60).
fn orient_i(a: [i128; 2], b: [i128; 2], c: [i128; 2]) -> i128 {
    ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])).signum()
}

/// Brute-force classification in integer arithmetic (independent of the hull code).
fn brute(points: &[[i128; 2]], v: [i128; 2]) -> Position {
    let on_seg = |a: [i128; 2], b: [i128; 2]| {
        orient_i(a, b, v) == 0
            && a[0].min(b[0]) <= v[0]
            && v[0] <= a[0].max(b[0])
            && a[1].min(b[1]) <= v[1]
            && v[1] <= a[1].max(b[1])
    };
    let mut inside = points.contains(&v);
    for (i, &a) in points.iter().enumerate() {
        for (j, &b) in points.iter().enumerate().skip(i + 1) {
            inside |= on_seg(a, b);
            for &c in &points[j + 1..] {
                if orient_i(a, b, c) != 0 {
                    let o = [orient_i(a, b, v), orient_i(b, c, v), orient_i(c, a, v)];
                    inside |= o.iter().all(|&s| s >= 0) || o.iter().all(|&s| s <= 0);
                }
            }
        }
    }
    if !inside {
        return Position::Outside;
    }
    let others: Vec<_> = points.iter().filter(|&&p| p != v).collect();
    let supported = others.is_empty()
        || others.iter().any(|&&p| {
            let s: Vec<i128> = points.iter().map(|&q| orient_i(v, p, q)).collect();
            s.iter().all(|&x| x >= 0) || s.iter().all(|&x| x <= 0)
        });
    if supported {
        Position::Boundary
    } else {
        Position::Interior
    }
}

/// xorshift64: a fixed, dependency-free random sequence.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
}

#[test]
fn exact_hull_test_matches_brute_force_on_random_degenerate_instances() {
    // Small integer grids make duplicates, collinear media and points on edges common.
    // Coordinates are scaled by 2^-3 and shifted by 2^10 (exact in f64) so the f64
    // code sees non-integers; the integer brute force works on the unscaled grid.
    let mut rng = Rng(0x9e3779b97f4a7c15);
    let mut seen = [0usize; 3];
    let to_f = |p: [i128; 2]| -> V2 { [1024.0 + p[0] as f64 / 8.0, 1024.0 + p[1] as f64 / 8.0] };
    for _ in 0..4000 {
        let n = rng.int(1, 8) as usize;
        let span = rng.int(1, 4);
        let pts: Vec<[i128; 2]> = (0..n)
            .map(|_| [rng.int(-span, span) as i128, rng.int(-span, span) as i128])
            .collect();
        // Mostly inside the media's box (interior and boundary cases), sometimes beyond.
        let w = if rng.int(0, 3) == 0 {
            span + 1
        } else {
            span / 2
        };
        let v = [rng.int(-w, w) as i128, rng.int(-w, w) as i128];
        let media: Vec<V2> = pts.iter().map(|&p| to_f(p)).collect();
        let got = classify(&hull(&media), to_f(v));
        let want = brute(&pts, v);
        assert_eq!(got, want, "media {pts:?} object {v:?}");
        seen[want as usize] += 1;
    }
    // The sample must exercise all three outcomes substantially.
    assert!(seen.iter().all(|&k| k > 300), "{seen:?}");
}

#[test]
fn near_degenerate_instances_are_exact_where_naive_floating_point_fails() {
    // Kettner et al.'s example: p = (0.5 + i u, 0.5 + j u), u = 2^-53, against the line
    // through (12, 12) and (24, 24). Exactly, p is on the line iff i == j. With media
    // {p, (12,12), (24,24)} the velocity (6, 6) is on the hull (a segment) iff i == j and
    // outside (beyond a thin triangle) otherwise. In units of u every coordinate is an
    // integer, so the brute force is exact.
    let u = 2f64.powi(-53);
    let s = 1i128 << 53;
    let mut naive_wrong = 0;
    for i in -24..=24 {
        for j in -24..=24 {
            let p = [0.5 + i as f64 * u, 0.5 + j as f64 * u];
            let (q, r) = ([12.0, 12.0], [24.0, 24.0]);
            let exact = orient2d(p, q, r);
            // (q - p) x (r - p) = 12 (j - i) u: p above the line y = x turns ccw.
            assert_eq!(exact, j.cmp(&i), "orient2d at i={i}, j={j}");
            let naive = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
            if naive.partial_cmp(&0.0) != Some(j.cmp(&i)) {
                naive_wrong += 1;
            }
            let media = [p, q, r];
            let ints = [
                [s / 2 + i as i128, s / 2 + j as i128],
                [12 * s, 12 * s],
                [24 * s, 24 * s],
            ];
            let v = [6.0, 6.0];
            assert_eq!(
                classify(&hull(&media), v),
                brute(&ints, [6 * s, 6 * s]),
                "i={i}, j={j}"
            );
        }
    }
    // The family has teeth: the naive determinant gets more than half of the 2401
    // signs wrong (1366 with IEEE double arithmetic without fused operations).
    assert!(naive_wrong > 1000, "naive wrong only {naive_wrong} times");
}

#[test]
fn summary_snapshot() {
    let cases: [(&str, &[V2], V2); 7] = [
        ("point hull, same velocity", &[[1.0, 1.0]], [1.0, 1.0]),
        ("point hull, other velocity", &[[1.0, 1.0]], [1.0, 2.0]),
        (
            "collinear media, between",
            &[[0.0, 0.0], [2.0, 2.0], [1.0, 1.0]],
            [0.5, 0.5],
        ),
        (
            "collinear media, beyond",
            &[[0.0, 0.0], [2.0, 2.0], [1.0, 1.0]],
            [3.0, 3.0],
        ),
        (
            "triangle, interior",
            &[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]],
            [1.0, 1.0],
        ),
        (
            "triangle, on an edge",
            &[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]],
            [2.0, 2.0],
        ),
        (
            "triangle, vertex",
            &[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]],
            [4.0, 0.0],
        ),
    ];
    let lines: Vec<String> = cases
        .iter()
        .map(|(name, media, v)| format!("{name}: {:?}", classify(&hull(media), *v)))
        .collect();
    let (_, out, _) = run(&["--object-velocity", "3,0"]);
    let r: Value = serde_json::from_str(&out).unwrap();
    // The claim lines end in a newline each.
    insta::assert_snapshot!(
        "locomotion_definition_summary",
        format!(
            "{}\n{}reason: {}",
            lines.join("\n"),
            common::verdict_lines(&r, " "),
            r["results"]["reason"].as_str().unwrap()
        )
    );
}

#[test]
fn bad_input_is_one_line_naming_the_flag_with_exit_code_2() {
    for flag in ["--object-velocity", "--medium-velocity"] {
        for value in [
            "1",
            "1,2,3",
            "a,b",
            "nan,1",
            "1,inf",
            "1e101,0",
            "0,-1e-101",
            ",",
            "",
        ] {
            let arg = format!("{flag}={value}");
            common::assert_bad_input(
                &[
                    "locomotion-definition",
                    "--quick",
                    "--json",
                    "--no-figures",
                    &arg,
                ],
                flag,
            );
        }
    }
}
