//! `mechkit inertia BODYFILE` and `mechkit com BODYFILE`: body files with shapes, holes,
//! meshes from OBJ files, units on the output, and their errors (located in the file).

use crate::util::{Dir, examples, num};

#[test]
fn inertia_of_a_composite_about_points_and_axes() {
    let dir = Dir::new();
    let file = examples().join("bodies/rod_two_spheres.toml");
    let file = file.to_str().unwrap();
    let j = dir.json(&["inertia", file, "--axis", "0, 0, 1", "--json"]);
    assert_eq!(num(&j, "/mass"), 2.0);
    assert!((num(&j, "/axis/moment") - 0.337_333_333_333).abs() < 1e-12);
    // about one end (x = -0.5 m): I_cm + M d² = 0.337333 + 2·0.25
    let end = dir.json(&[
        "inertia",
        file,
        "--about",
        "-50 cm, 0, 0",
        "--axis",
        "0,1,0",
        "--json",
    ]);
    assert!((num(&end, "/axis/moment") - 0.837_333_333_333).abs() < 1e-12);
    assert!((num(&end, "/inertia_about/2/2") - 0.837_333_333_333).abs() < 1e-12);
    // principal moments ascending: the rod's own axis (x) has the smallest
    assert!((num(&j, "/principal_moments/0") - 0.004).abs() < 1e-15);
    assert!((num(&j, "/principal_axes/0/0") - 1.0).abs() < 1e-15);
    // in g·cm² and rescaled to 4 kg (everything doubles)
    let g = dir.json(&[
        "inertia",
        file,
        "--in",
        "g*cm^2",
        "--total-mass",
        "4 kg",
        "--json",
    ]);
    assert!((num(&g, "/inertia_cm/2/2") - 2.0 * 0.337_333_333_333e7).abs() < 1e-3);
    assert_eq!(g["unit"], "g*cm^2");
    // the text names the parts and the principal axes
    let text = dir.run(&["inertia", file]);
    text.assert_code(0);
    assert!(
        text.stdout.contains("left sphere (sphere)"),
        "{}",
        text.stdout
    );
    assert!(text.stdout.contains("principal moments"));
}

#[test]
fn centre_of_mass_of_body_files_with_holes_and_meshes() {
    let dir = Dir::new();
    let cube = examples().join("bodies/cube_with_hole.toml");
    let j = dir.json(&["com", cube.to_str().unwrap(), "--json"]);
    assert!((num(&j, "/total_mass") - 7850.0 * (1e-3 - 0.125e-3)).abs() < 1e-9);
    assert!((num(&j, "/centre_of_mass/0") + 0.025 * 0.125 / 0.875).abs() < 1e-15);
    assert_eq!(j["parts"][1]["hole"], true);
    // a tetrahedron from an OBJ file next to the body file: CM at the mean of the vertices
    dir.create(
        "tet.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    );
    dir.create(
        "tet.toml",
        "[[part]]\nshape = \"mesh\"\nfile = \"tet.obj\"\ndensity = 6\nposition = [1, 2, 3]\n",
    );
    let t = dir.json(&["com", "tet.toml", "--json"]);
    assert!((num(&t, "/total_mass") - 1.0).abs() < 1e-15);
    for (k, c) in [1.25, 2.25, 3.25].iter().enumerate() {
        assert!((num(&t, &format!("/centre_of_mass/{k}")) - c).abs() < 1e-15);
    }
    // point masses inline
    let em = dir.json(&[
        "com",
        "--mass",
        "5.972e24 kg@0, 0",
        "--mass",
        "7.342e22 kg@384400 km, 0",
        "--json",
    ]);
    assert!((num(&em, "/centre_of_mass/0") - 4.6686e6).abs() < 1e3);
}

#[test]
fn body_file_errors_say_where_and_what_to_write() {
    let dir = Dir::new();
    let write = |text: &str| {
        dir.create("b.toml", text);
    };
    write("[[part]]\nshape = \"sphere\"\nradius = \"2 kg\"\nmass = 1\n");
    dir.run(&["inertia", "b.toml"])
        .assert_bad_input(&["b.toml:3:10", "`radius` must have dimension m"]);
    write("[[part]]\nshape = \"sphre\"\n");
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["unknown shape `sphre`", "sphere"]);
    write("[[part]]\nshape = \"disk\"\nradius = 1\nlength = 2\nmass = 1\n");
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["b.toml:4:1", "a disk has no `length`"]);
    write("[[part]]\nshape = \"plate\"\nwidth = 1\nheight = 1\ndensity = \"7800 kg/m^3\"\n");
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["b.toml:5", "kg/m^2", "7.8 kg/m^2"]);
    write("density = \"7800 kg/m^3\"\n[[part]]\nshape = \"disk\"\nradius = 1\n");
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["density", "this disk needs"]);
    write("[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\n");
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["b.toml:1", "mass", "density"]);
    write(
        "[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\nmass = 1\n[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\nmass = 1\nhole = true\n",
    );
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["total mass", "holes cancel"]);
    write("[[part]]\nshape = \"polygon\"\nvertices = [[0, 0], [1, 1], [1, 0], [0, 1]]\nmass = 1\n");
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["b.toml:3", "crosses itself"]);
    write("[[part]]\nshape = \"triangle\"\nvertices = [[0, 0], [1, 1], [2, 2]]\nmass = 1\n");
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["degenerate triangle", "zero area"]);
    write(
        "[[part]]\nshape = \"mesh\"\nvertices = [[0,0,0],[1,0,0],[0,1,0],[0,0,1]]\nfaces = [[1,3,2],[1,2,4],[1,4,3]]\nmass = 1\n",
    );
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["b.toml:4", "not closed"]);
    write("[[part]]\nshape = \"mesh\"\nfile = \"missing.obj\"\nmass = 1\n");
    dir.run(&["com", "b.toml"])
        .assert_bad_input(&["b.toml:3", "cannot read the mesh"]);
    dir.run(&["inertia", "nothing.toml"])
        .assert_bad_input(&["cannot read nothing.toml"]);
    write("[[part]]\nshape = \"point\"\nmass = 1\n");
    dir.run(&["inertia", "b.toml", "--in", "kg"])
        .assert_bad_input(&["--in", "moment of inertia"]);
    dir.run(&["inertia", "b.toml", "--axis", "0, 0, 0"])
        .assert_bad_input(&["--axis", "no length"]);
}

#[test]
fn trajectory_has_the_centre_of_mass_and_the_kinetic_energy_split() {
    // two bodies on a spring, thrown in uniform gravity: the centre of mass falls freely
    // (cm.ay = -g, cm.vx constant) while the bodies oscillate about it
    let dir = Dir::new();
    dir.create(
        "pair.toml",
        r#"
dimensions = 2
[[body]]
name = "a"
mass = "1 kg"
position = [0, 0]
velocity = ["3 m/s", "10 m/s"]
[[body]]
name = "b"
mass = "3 kg"
position = ["1 m", 0]
velocity = [0, "2 m/s"]
[[force]]
kind = "uniform-gravity"
g = "9.81 m/s^2"
[[force]]
kind = "spring"
k = "50 N/m"
rest_length = "1 m"
between = ["a", "b"]
[integrator]
method = "rk4"
dt = "1 ms"
[stop]
t_max = "1 s"
"#,
    );
    dir.run(&["run", "pair.toml", "--out", "out", "--no-plots"])
        .assert_code(0);
    let csv = crate::util::Csv::parse(&dir.read("out/trajectory.csv"));
    let col = |n: &str| csv.column(n);
    for row in &csv.rows {
        let t = row[0];
        assert!((row[col("cm.vx")] - 0.75).abs() < 1e-12);
        assert!((row[col("cm.ay")] + 9.81).abs() < 1e-9);
        assert!((row[col("cm.y")] - (4.0 * t - 4.905 * t * t)).abs() < 1e-9);
        let (k, kc, ki) = (row[col("K")], row[col("K_cm")], row[col("K_internal")]);
        assert!((k - kc - ki).abs() < 1e-12 * k);
        assert!(ki > 0.0);
    }
    // the energy ledger split: the centre of mass falls in gravity (external), the spring's
    // energy trades with the motion about the centre of mass (internal)
    let j = dir.read_json("out/summary.json");
    let cm = &j["centre_of_mass"];
    let total = num(cm, "/total_mass");
    let v2 = |p: &str| {
        (0..2)
            .map(|k| num(cm, &format!("{p}/velocity/{k}")).powi(2))
            .sum::<f64>()
    };
    let d_kcm = 0.5 * total * (v2("/end") - v2("/start"));
    let d_kint = num(cm, "/internal_kinetic_end") - num(cm, "/internal_kinetic_start");
    let (d_uint, d_uext) = (
        num(cm, "/internal_potential_change"),
        num(cm, "/external_potential_change"),
    );
    assert!((d_kcm + d_uext).abs() < 1e-8, "{d_kcm} {d_uext}");
    assert!((d_kint + d_uint).abs() < 1e-8, "{d_kint} {d_uint}");
    assert!(d_uint.abs() > 1e-3);
}
