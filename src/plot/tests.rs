//! Figure style tests: determinism, embedded font, robustness to degenerate data.

use super::*;

fn demo() -> Chart {
    let pts: Vec<(f64, f64)> = (0..50)
        .map(|i| (i as f64 * 0.1, (i as f64 * 0.1).sin()))
        .collect();
    Chart::new("Determinism test", "t (s)", "x (m)")
        .line("sin", pts.clone())
        .dashed("shifted", pts.iter().map(|p| (p.0, p.1 + 0.2)).collect())
        .points("samples", pts.iter().step_by(5).copied().collect())
        .vline(2.0, "t = 2 s")
        .hline(0.0, "zero")
        .band(1.0, 1.5, "phase")
}

/// Renders into an RGB buffer (white background) and returns it.
fn raster<D: Drawing>(d: &D, size: (u32, u32)) -> Vec<u8> {
    ensure_font();
    let mut buf = vec![0u8; (size.0 * size.1 * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        root.fill(&WHITE).unwrap();
        d.draw(&root).unwrap();
        root.present().unwrap();
    }
    buf
}

#[test]
fn same_bytes_on_every_render() {
    let dir = tempfile::tempdir().unwrap();
    let a = save_chart(&demo(), dir.path().join("a"), "c").unwrap();
    let b = save_chart(&demo(), dir.path().join("b"), "c").unwrap();
    assert_eq!(a.len(), 2);
    for (pa, pb) in a.iter().zip(&b) {
        let (ba, bb) = (std::fs::read(pa).unwrap(), std::fs::read(pb).unwrap());
        assert!(ba.len() > 1000, "{pa} is suspiciously small");
        assert_eq!(ba, bb, "{pa} differs between two renders");
    }
    assert!(a[0].ends_with("c.svg") && a[1].ends_with("c.png"));
    let png = std::fs::read(&a[1]).unwrap();
    assert_eq!(&png[1..4], b"PNG");
}

#[test]
fn the_embedded_font_draws_text_into_png() {
    // A chart without data: the top 45 rows hold only the title, so dark pixels there
    // are glyphs. Without a usable font plotters would fail or leave them white.
    let size = (600, 400);
    let buf = raster(&Chart::new("TITLE WITH GLYPHS", "x", "y"), size);
    let dark = buf[..(45 * size.0 * 3) as usize]
        .chunks(3)
        .filter(|p| p.iter().all(|&c| c < 128))
        .count();
    let blank = raster(&Chart::new("", "x", "y"), size);
    let dark_blank = blank[..(45 * size.0 * 3) as usize]
        .chunks(3)
        .filter(|p| p.iter().all(|&c| c < 128))
        .count();
    // Without a title only axis ends may reach into the band.
    assert!(
        dark > dark_blank + 200,
        "title adds only {} dark pixels",
        dark - dark_blank
    );
}

#[test]
fn degenerate_inputs_do_not_panic() {
    let size = (400, 300);
    let nan = f64::NAN;
    let inf = f64::INFINITY;
    let charts = [
        Chart::new("", "", ""),
        Chart::new("empty series", "x", "y")
            .line("a", vec![])
            .points("b", vec![])
            .dashed("c", vec![]),
        Chart::new("bad points", "x", "y").line("a", vec![(nan, 1.0), (inf, 2.0), (1.0, -inf)]),
        Chart::new("one point", "x", "y")
            .line("a", vec![(1.0, 1.0)])
            .points("p", vec![(1.0, 1.0)]),
        Chart::new("flat", "x", "y").line("a", vec![(0.0, 3.0), (1.0, 3.0)]),
        Chart::new("log", "x", "y")
            .log_x()
            .log_y()
            .line("a", vec![(0.0, 1.0), (-1.0, 2.0), (1.0, 0.0)]),
        Chart::new("log ok", "x", "y")
            .log_x()
            .log_y()
            .line("a", vec![(1e-6, 1e3), (1e3, 1e-9)]),
        Chart::new("ranges", "x", "y")
            .x_range(1.0, 1.0)
            .y_range(nan, 2.0)
            .line("a", vec![(0.0, 0.0), (5.0, 5.0)]),
        Chart::new("clip", "x", "y")
            .x_range(0.0, 1.0)
            .y_range(0.0, 1.0)
            .line("a", vec![(-5.0, -5.0), (5.0, 5.0)]),
        Chart::new("refs", "x", "y")
            .vline(nan, "v")
            .hline(inf, "h")
            .band(nan, 1.0, "b")
            .band(2.0, 1.0, ""),
        Chart::new("huge", "x", "y").line("a", vec![(0.0, 1e300), (1.0, -1e300)]),
        Chart::new("tiny", "x", "y")
            .line("a", vec![(0.0, 1e-300), (1e-300, 0.0)])
            .log_x(),
    ];
    for c in &charts {
        raster(c, size);
    }
    raster(
        &Panels {
            charts: &[],
            cols: 2,
        },
        size,
    );
    raster(
        &Panels {
            charts: &charts[..3],
            cols: 2,
        },
        size,
    );
    let dir = tempfile::tempdir().unwrap();
    assert_eq!(save_panels(&[], 0, dir.path(), "none").unwrap().len(), 2);
    assert_eq!(
        save_drawing(&charts[0], dir.path(), "tiny", (0, 0))
            .unwrap()
            .len(),
        2
    );
}

#[test]
fn degenerate_heat_maps_do_not_panic() {
    let (nan, inf) = (f64::NAN, f64::INFINITY);
    let maps = [
        HeatMap::new("empty", "x", "y", vec![], vec![], vec![], "v"),
        HeatMap::new(
            "ragged",
            "x",
            "y",
            vec![0.0, 1.0, 2.0],
            vec![0.0, 1.0],
            vec![vec![1.0]],
            "v",
        ),
        HeatMap::new(
            "nan",
            "x",
            "y",
            vec![nan, 1.0],
            vec![2.0, 1.0],
            vec![vec![nan, inf], vec![1.0, 1.0]],
            "v",
        )
        .overlay(Series::line("o", vec![(nan, 0.0), (0.5, 0.5)])),
    ];
    for h in &maps {
        raster(h, (500, 300));
    }
}

#[test]
fn heat_map_is_deterministic_and_viridis_is_monotone_in_lightness() {
    let xs: Vec<f64> = (0..20).map(|i| i as f64 * 0.05).collect();
    let ys: Vec<f64> = (0..15).map(|i| i as f64 * 0.1).collect();
    let v: Vec<Vec<f64>> = ys
        .iter()
        .map(|y| xs.iter().map(|x| x * y).collect())
        .collect();
    let h = HeatMap::new("map", "a (1)", "b (1)", xs, ys, v, "a b (1)").overlay(Series::dashed(
        "a b = 0.5",
        (1..20)
            .map(|i| (i as f64 * 0.05, 0.5 / (i as f64 * 0.05)))
            .collect(),
    ));
    assert_eq!(raster(&h, (700, 450)), raster(&h, (700, 450)));
    let luma = |c: RGBColor| 0.299 * c.0 as f64 + 0.587 * c.1 as f64 + 0.114 * c.2 as f64;
    for k in 0..20 {
        assert!(luma(viridis(k as f64 / 20.0)) < luma(viridis((k + 1) as f64 / 20.0)));
    }
    assert_eq!(viridis(f64::NAN), RGBColor(190, 190, 190));
}

#[test]
#[ignore = "writes demo figures to /tmp/plot-demo for a visual check"]
fn demo_figures() {
    let dir = std::path::Path::new("/tmp/plot-demo");
    save_chart(&demo(), dir, "chart").unwrap();
    let log = Chart::new("Log axes", "step h (s)", "error (m)")
        .log_x()
        .log_y()
        .line(
            "Euler",
            (0..10)
                .map(|i| (10f64.powf(-i as f64 / 3.0), 10f64.powf(-i as f64 / 3.0)))
                .collect(),
        )
        .points(
            "RK4",
            (0..10)
                .map(|i| {
                    (
                        10f64.powf(-i as f64 / 3.0),
                        10f64.powf(-4.0 * i as f64 / 3.0),
                    )
                })
                .collect(),
        )
        .legend(Legend::LowerRight);
    save_panels(&[demo(), log], 2, dir, "panels").unwrap();
    let xs: Vec<f64> = (0..40).map(|i| i as f64 * 0.05).collect();
    let ys: Vec<f64> = (0..30).map(|i| i as f64 * 0.1).collect();
    let v: Vec<Vec<f64>> = ys
        .iter()
        .map(|y| xs.iter().map(|x| (x * y).sin()).collect())
        .collect();
    let h = HeatMap::new("Heat map", "a (m)", "b (s)", xs, ys, v, "sin(ab) (1)").overlay(
        Series::dashed(
            "ab = 1",
            (2..40)
                .map(|i| (i as f64 * 0.05, 1.0 / (i as f64 * 0.05)))
                .collect(),
        ),
    );
    save_heatmap(&h, dir, "heat").unwrap();
}

#[test]
fn an_unwritable_folder_is_an_io_error() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("plain-file");
    std::fs::write(&file, b"x").unwrap();
    let err = save_chart(&demo(), &file, "c").unwrap_err();
    assert!(matches!(err, WorkbookError::Io(_)), "{err:?}");
}

#[test]
fn figure_names_are_kebab_case() {
    for good in [
        "time-series",
        "speed-map",
        "work-precision-block-drift",
        "c",
        "a1-b2",
    ] {
        assert!(is_kebab(good), "{good}");
    }
    for bad in [
        "time_series",
        "Speed-map",
        "a--b",
        "-a",
        "a-",
        "",
        "a.b",
        "θ",
    ] {
        assert!(!is_kebab(bad), "{bad}");
    }
    let dir = tempfile::tempdir().unwrap();
    let err = save_chart(&demo(), dir.path(), "work_precision").unwrap_err();
    assert!(err.to_string().contains("kebab-case"), "{err}");
    assert!(!dir.path().join("work_precision.png").exists());
}

#[test]
fn noisy_lines_draw_no_stroke_outside_the_frame() {
    // The start of the energy budget's residual (points read back from its SVG): a noisy
    // trace that turns back on itself, where the bitmap backend's miter joins once drew
    // a spike down through the tick labels to the picture's edge.
    let pts = vec![
        (0.0, 1e-16),
        (0.002962962962962963, 4.422514763163035e-14),
        (0.002962962962962963, 3.152736422488379e-14),
        (0.005925925925925926, 1.8635506769443995e-13),
        (0.005925925925925926, 2.302526962179327e-13),
        (0.005925925925925926, 3.515052035464467e-13),
        (0.008888888888888889, 6.203701867014303e-14),
        (0.011851851851851851, 1.8635506769443995e-13),
        (0.011851851851851851, 7.347536163492159e-14),
        (0.011851851851851851, 8.915202939363682e-13),
        (0.014814814814814815, 9.70234336986844e-13),
        (0.014814814814814815, 2.3164844878192164e-11),
        (0.014814814814814815, 1.101525995249214e-12),
        (0.017777777777777778, 7.665040178861088e-14),
        (0.02074074074074074, 1.3610004466105507e-12),
        (0.02074074074074074, 1.3046246029575035e-12),
        (0.023703703703703703, 1.9916480638308544e-12),
        (0.023703703703703703, 5.839883715540168e-13),
        (0.023703703703703703, 1.874847203231364e-11),
        (0.02666666666666667, 1.874847203231364e-11),
        (0.02962962962962963, 1.7971866168105798e-11),
        (0.03259259259259259, 1.7971866168105798e-11),
        (0.035555555555555556, 1.7971866168105798e-11),
        (0.035555555555555556, 1.874847203231364e-11),
        (0.035555555555555556, 1.7971866168105798e-11),
        (0.03851851851851852, 1.874847203231364e-11),
        (0.04148148148148148, 1.0817346343248566e-11),
        (0.04148148148148148, 1.3943023372816669e-11),
        (0.044444444444444446, 1.3943023372816669e-11),
        (0.047407407407407405, 1.3943023372816669e-11),
        (0.05037037037037037, 1.3943023372816669e-11),
        (0.05333333333333334, 1.2811841244764894e-11),
        (0.05333333333333334, 1.2281144608535838e-11),
        (0.056296296296296296, 1.128478887407722e-11),
        (0.056296296296296296, 1.5174079748634928e-11),
        (0.05925925925925926, 1.4545533630506651e-11),
        (0.06222222222222222, 1.3943023372816669e-11),
        (0.06518518518518518, 1.1772430676769291e-11),
        (0.06518518518518518, 1.3943023372816669e-11),
        (0.06814814814814815, 1.3943023372816669e-11),
        (2.0, 1e-9),
    ];
    let c = Chart::new("", "t (s)", "r (J)").line("", pts).log_y();
    let size = (800, 540);
    let buf = raster(&c, size);
    let blue = |p: &[u8]| p[2] > 120 && p[0] < 80 && p[1] > 60 && p[1] < 170;
    // rows below the x axis (the last 50 rows hold only tick labels and the description)
    let below = buf[(size.1 - 50) as usize * size.0 as usize * 3..]
        .chunks(3)
        .filter(|p| blue(p))
        .count();
    assert_eq!(below, 0, "{below} line pixels below the frame");
    let all = buf.chunks(3).filter(|p| blue(p)).count();
    assert!(all > 200, "the line itself is drawn ({all} pixels)");
}
