//! Many-particle molecular dynamics: neighbour lists against all pairs, lattices and
//! velocities, a two-atom LJ pair against its energy diagram, the LJ melt's energy and its
//! thread-independence.

mod lattice;
mod melt;
mod neighbour;
mod pair;
mod rebuild;
