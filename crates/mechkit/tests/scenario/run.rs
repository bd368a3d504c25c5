//! Running scenarios: outputs are written atomically and kept when a run diverges; a missing
//! t_max is bounded with a warning.

use mechkit::scenario::Scenario;

const DIVERGING: &str = r#"
title = "falls onto a singularity"
[[body]]
name = "probe"
mass = "1e30 kg"
position = "1 m"
velocity = "-1 m/s"
[[force]]
name = "pull"
kind = "expression"
F = "-1/x^2"
[integrator]
method = "euler-cromer"
dt = "0.25 s"
[stop]
t_max = "10 s"
"#;

#[test]
fn divergence_keeps_the_trajectory_and_writes_the_summary() {
    let dir = tempfile::tempdir().unwrap();
    let s = Scenario::from_str("diverging.toml", DIVERGING).unwrap();
    let out = s.run_to_dir(dir.path()).unwrap();
    assert!(out.failed());
    assert_eq!(out.summary.stop_reason, "diverged");
    let d = out.summary.divergence.as_ref().unwrap();
    assert!(d.quantity.contains("pull"), "{d:?}");
    assert_eq!(d.t, 1.0);
    let csv = std::fs::read_to_string(dir.path().join("trajectory.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().collect();
    // no force has a potential, so there are no U and E columns
    assert_eq!(rows[0], "t,probe.x,probe.vx,K,work.pull,power.pull");
    assert_eq!(rows.len(), 1 + 5, "t = 0 … 1 s");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("summary.json")).unwrap())
            .unwrap();
    assert_eq!(json["stop_reason"], "diverged");
    // no temporary files are left behind
    let names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(names.iter().all(|n| !n.ends_with(".partial")), "{names:?}");
}

#[test]
fn missing_t_max_is_bounded_with_a_warning() {
    let text = r#"
[[body]]
mass = "1 kg"
[integrator]
method = "euler"
dt = "1 s"
[stop]
when = "x < -1"
"#;
    let s = Scenario::from_str("forever.toml", text).unwrap();
    assert!(s.warnings.iter().any(|w| w.contains("t_max")));
    let out = s.run().unwrap();
    assert_eq!(out.summary.stop_reason, "max_steps");
    assert_eq!(out.summary.steps, mechkit::simulate::DEFAULT_MAX_STEPS);
    assert!(
        out.summary
            .warnings
            .iter()
            .any(|w| w.contains("never became true"))
    );
}

#[test]
fn decimation_keeps_the_last_row() {
    let dir = tempfile::tempdir().unwrap();
    let text =
        std::fs::read_to_string(crate::util::workspace().join("examples/feather.toml")).unwrap();
    let s = Scenario::from_str("feather.toml", &text).unwrap();
    let out = s.run_to_dir(dir.path()).unwrap();
    let csv = std::fs::read_to_string(dir.path().join("trajectory.csv")).unwrap();
    let last: Vec<f64> = csv
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    assert!((last[0] - out.summary.t_end).abs() < 1e-15);
    assert!(last[1].abs() < 1e-12, "ends on the floor");
    // every 10th of 4835 steps, plus the first row and the located landing
    assert_eq!(out.summary.files.trajectory_rows, 484 + 1);
}

/// The trajectory kept in memory is `trajectory.csv`, number for number, in a scenario with
/// every kind of column: two bodies (centre of mass), a rigid body turning in space, a joint,
/// a potential, decimation and the last row.
#[test]
fn the_trajectory_in_memory_is_the_csv_number_for_number() {
    let text = r#"
title = "a top and a ball on a spring"
dimensions = 3
[[body]]
name = "ball"
mass = "0.2 kg"
position = [0.3, 0, 0.1]
[[rigid_body]]
name = "top"
mass = "0.5 kg"
inertia = [2e-4, 2e-4, 3e-4]
orientation = { axis = [1, 0, 0], angle = 0.3 }
position = [0, "-0.04*sin(0.3)", "0.04*cos(0.3)"]
omega = [0, "-100*sin(0.3)", "100*cos(0.3)"]
points = { tip = [0, 0, -0.04] }
[[force]]
kind = "uniform-gravity"
[[force]]
kind = "spring"
between = ["ball", "top"]
k = "5 N/m"
[[joint]]
name = "pivot"
kind = "hinge"
a = "top.tip"
[integrator]
method = "rk4"
dt = "1 ms"
[stop]
t_max = "0.1015 s"
[output]
every = 7
"#;
    let dir = tempfile::tempdir().unwrap();
    let s = Scenario::from_str("top.toml", text).unwrap();
    let written = s.run_to_dir(dir.path()).unwrap();
    let (out, table) = s.run_with_trajectory().unwrap();
    assert_eq!(out.summary.steps, written.summary.steps);
    let csv = std::fs::read_to_string(dir.path().join("trajectory.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let names: Vec<&str> = table.columns().iter().map(|c| c.name.as_str()).collect();
    assert_eq!(header, names);
    assert!(names.contains(&"top.q3") && names.contains(&"cm.ax") && names.contains(&"U"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), table.len());
    // every 7th of 101 steps, and the last (t = 0.1015 s)
    assert_eq!(table.len(), 16);
    for (i, col) in table.data().iter().enumerate() {
        for (r, row) in rows.iter().enumerate() {
            assert!(
                col[r].to_bits() == row[i].to_bits(),
                "{} row {r}: {} vs {}",
                names[i],
                col[r],
                row[i]
            );
        }
    }
    assert_eq!(table.column("t").unwrap().last(), Some(&0.1015));
}

/// A hand-written Euler-Cromer loop over the scenario's model (`evaluate_model`) is the run,
/// bit for bit, when its steps are the run's: `t_k = k dt` exactly, so each step is
/// `t_{k+1} − t_k` (a plain `dt` differs from it in the last bits, and the two loops then
/// part at the level of rounding); each force's value, power and potential are its law.
#[test]
fn a_hand_written_loop_over_the_model_is_the_run() {
    let path = crate::util::workspace().join("examples/feather.toml");
    let overrides = mechkit::scenario::sweep::ConstantOverride::parse_list("Dmg=4").unwrap();
    let mut s = Scenario::load_with(&path, &overrides).unwrap();
    s.t_max = Some(1.0);
    let run = s.run().unwrap();
    assert_eq!(run.summary.steps, 1000);
    let (dt, g, dmg, m) = (1e-3, 9.8, 4.0, 1e-3);
    let (mut x, mut v) = (vec![2.4], vec![0.0]);
    for k in 0..1000 {
        let t = f64::from(k) * dt;
        let model = s.evaluate_model(&[t], &x, &v).unwrap();
        // the forces' own laws at this state
        assert_eq!(model.forces, ["gravity", "air"]);
        assert_eq!(model.force[0], -m * g);
        assert_eq!(model.force[1], -m * g * dmg * v[0] * v[0].abs());
        assert_eq!(model.power[0], -m * g * v[0]);
        assert_eq!(model.potential[0], m * g * x[0]);
        assert!(model.potential[1].is_nan());
        let h = f64::from(k + 1) * dt - t;
        v[0] += h * model.accel[0];
        x[0] += h * v[0];
    }
    let (q_end, v_end) = run.report.final_state.qv();
    assert_eq!(
        x[0].to_bits(),
        q_end[0].to_bits(),
        "{} vs {}",
        x[0],
        q_end[0]
    );
    assert_eq!(
        v[0].to_bits(),
        v_end[0].to_bits(),
        "{} vs {}",
        v[0],
        v_end[0]
    );
}

/// Many states at once, and a mechanism: at each state of a rolling cylinder's run the
/// forces (gravity and the slope's contact, from the applied sum) add up to `m a` for the
/// centre and `I α` for the angle, and the wrong number of coordinates is an error naming them.
#[test]
fn the_model_of_a_mechanism_at_many_states() {
    let path = crate::util::workspace().join("examples/rigid/rolling_incline.toml");
    let s = Scenario::load(&path).unwrap();
    let (out, table) = s.run_with_trajectory().unwrap();
    assert!(!out.failed());
    let names = s.coordinate_names();
    assert_eq!(names.len(), s.dof());
    assert!(names.iter().any(|n| n == "cylinder.x"), "{names:?}");
    let dof = s.dof();
    let rows = table.len();
    let (mut q, mut v) = (Vec::new(), Vec::new());
    let col = |name: &str| table.column(name).unwrap();
    let t = col("t").to_vec();
    for r in 0..rows {
        for name in &names {
            let (qn, vn) = match name.rsplit_once('.') {
                Some((b, "x")) => (format!("{b}.x"), format!("{b}.vx")),
                Some((b, "y")) => (format!("{b}.y"), format!("{b}.vy")),
                _ => (format!("{name}.theta"), format!("{name}.omega")),
            };
            if let (Some(a), Some(b)) = (table.column(&qn), table.column(&vn)) {
                q.push(a[r]);
                v.push(b[r]);
            } else {
                // a joint's mode: as at the start
                let i = names.iter().position(|n| n == name).unwrap();
                let (q0, v0) = s.initial.qv();
                q.push(q0[i]);
                v.push(v0[i]);
            }
        }
    }
    let model = s.evaluate_model(&t, &q, &v).unwrap();
    assert_eq!(model.states, rows);
    let nf = model.forces.len();
    let mass = s.system.masses()[0];
    for r in 0..rows {
        for c in 0..2 {
            let sum: f64 = (0..nf).map(|i| model.force[(r * nf + i) * dof + c]).sum();
            let ma = mass * model.accel[r * dof + c];
            assert!(
                (sum - ma).abs() < 1e-9 * (1.0 + ma.abs()),
                "row {r}: {sum} vs {ma}"
            );
        }
    }
    let e = s.evaluate_model(&[0.0], &[1.0], &[0.0]).unwrap_err();
    assert!(e.message.contains("cylinder.x"), "{}", e.message);
}
