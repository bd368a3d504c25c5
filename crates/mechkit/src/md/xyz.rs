//! Trajectories as extended XYZ frames (read by OVITO, VMD and ASE).
//!
//! Each frame: the atom count; a comment line with `Lattice="…"` (the box's cell vectors,
//! 1 on unused axes), `Properties=species:S:1:pos:R:3:velo:R:3`, `Time=` and `pbc="T T T"`;
//! then one line per atom.

use std::io::{self, Write};

use super::{Md, PairPotential};

impl<P: PairPotential> Md<P> {
    /// Writes the current state as one extended-XYZ frame, every atom named `species`.
    pub fn write_xyz_frame<W: Write>(&self, out: &mut W, species: &str) -> io::Result<()> {
        let l = self.sim_box.lengths();
        let p = self.sim_box.is_periodic();
        let edge = |a: usize| if l[a] > 0.0 { l[a] } else { 1.0 };
        let flag = |a: usize| if p[a] { 'T' } else { 'F' };
        writeln!(out, "{}", self.len())?;
        writeln!(
            out,
            "Lattice=\"{} 0 0 0 {} 0 0 0 {}\" Properties=species:S:1:pos:R:3:velo:R:3 Time={} pbc=\"{} {} {}\"",
            edge(0),
            edge(1),
            edge(2),
            self.steps as f64 * self.config.dt,
            flag(0),
            flag(1),
            flag(2)
        )?;
        for (x, v) in self.positions().iter().zip(&self.velocities()) {
            writeln!(
                out,
                "{species} {:.8} {:.8} {:.8} {:.8} {:.8} {:.8}",
                x[0], x[1], x[2], v[0], v[1], v[2]
            )?;
        }
        Ok(())
    }
}
