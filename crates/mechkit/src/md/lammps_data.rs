//! The texts of a LAMMPS export besides the input script: the data file (`atom_style
//! atomic`: header, box, `Masses`, `Atoms # atomic`, `Velocities`) and the pair table of a law
//! without a native LAMMPS style.

use std::fmt::Write as _;

use crate::Real;

use super::lammps::{TABLE_INNER, TABLE_POINTS};
use super::{Md, PairPotential};

/// `x` in full precision: Rust's shortest representation that reads back to the same `f64`,
/// in exponent form when plain digits would be long (`1e-7`, not `0.0000001`).
pub(crate) fn num(x: Real) -> String {
    if x == 0.0 || (1e-5..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// The box bounds `(lo, hi)` of each LAMMPS axis: a periodic axis `0 L`; an open one spans
/// the box and every atom with a margin of the cut-off (LAMMPS shrink-wraps it at once); the
/// axes beyond the dimension `−r_c r_c` around the atoms' zero coordinate.
pub(crate) fn bounds<P: PairPotential>(md: &Md<P>) -> [(Real, Real); 3] {
    let dim = md.sim_box.dim();
    let lengths = md.sim_box.lengths();
    let periodic = md.sim_box.is_periodic();
    let rc = md.potential.cutoff();
    std::array::from_fn(|a| {
        if a >= dim {
            (-rc, rc)
        } else if periodic[a] {
            (0.0, lengths[a])
        } else {
            let (lo, hi) =
                md.x.iter()
                    .fold((0.0, lengths[a]), |(lo, hi): (Real, Real), p| {
                        (lo.min(p[a]), hi.max(p[a]))
                    });
            (lo - rc, hi + rc)
        }
    })
}

/// The data file of the state of `md`: one atom type of the run's mass, atoms numbered from 1
/// in mechkit's order.
pub(crate) fn data_file<P: PairPotential>(md: &Md<P>) -> String {
    let n = md.len();
    let mut s = format!(
        "LAMMPS data file written by mechkit md ({n} atoms, {}-D, atom_style atomic)\n\n",
        md.sim_box.dim()
    );
    let _ = writeln!(s, "{n} atoms\n1 atom types\n");
    for ((lo, hi), axis) in bounds(md).into_iter().zip(["x", "y", "z"]) {
        let _ = writeln!(s, "{} {} {axis}lo {axis}hi", num(lo), num(hi));
    }
    let _ = writeln!(
        s,
        "\nMasses\n\n1 {}\n\nAtoms # atomic\n",
        num(md.config.mass)
    );
    for (i, p) in md.positions().iter().enumerate() {
        let _ = writeln!(s, "{} 1 {} {} {}", i + 1, num(p[0]), num(p[1]), num(p[2]));
    }
    s.push_str("\nVelocities\n\n");
    for (i, v) in md.velocities().iter().enumerate() {
        let _ = writeln!(s, "{} {} {} {}", i + 1, num(v[0]), num(v[1]), num(v[2]));
    }
    s
}

/// The radii of the table: [`TABLE_POINTS`] evenly spaced in r² from `TABLE_INNER`·r_c to r_c,
/// computed as LAMMPS recomputes them from `N n RSQ rlo rhi`.
fn table_radii(cutoff: Real) -> impl Iterator<Item = Real> {
    let lo = TABLE_INNER * cutoff;
    let span = cutoff * cutoff - lo * lo;
    let last = (TABLE_POINTS - 1) as Real;
    (0..TABLE_POINTS).map(move |i| (lo * lo + span * i as Real / last).sqrt())
}

/// The pair table of `potential` (keyword `MECHKIT`): index, r, U(r), F(r) = −U'(r), for
/// `pair_style table spline TABLE_POINTS`.
pub(crate) fn pair_table<P: PairPotential>(potential: &P) -> String {
    let rc = potential.cutoff();
    let mut s = format!(
        "# mechkit md pair table: U(r) and F(r) = -dU/dr of the run's potential at {TABLE_POINTS}\n\
         # points evenly spaced in r^2; read with `pair_style table spline {TABLE_POINTS}`\n\n\
         MECHKIT\nN {TABLE_POINTS} RSQ {} {}\n\n",
        num(TABLE_INNER * rc),
        num(rc)
    );
    for (i, r) in table_radii(rc).enumerate() {
        let (u, f_over_r) = potential.energy_force(r * r);
        let _ = writeln!(s, "{} {} {} {}", i + 1, num(r), num(u), num(f_over_r * r));
    }
    s
}
