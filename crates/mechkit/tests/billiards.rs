//! The acceptance run too slow for a debug build: 100 elastic disks in a box until 10⁴
//! impacts. A test target of its own, so that its release build compiles this file and the
//! library only (CI: `cargo test --release -p mechkit --features image --test billiards --
//! --ignored`, the library's features those of the command line's release build, which it
//! then shares).

#[path = "collisions/disks.rs"]
mod disks;

use disks::disks_in_a_box;

/// 100 elastic disks in a box until 10⁴ impacts: kinetic energy kept and no overlap. The
/// disk-disk impacts conserve momentum to 1e-12 (the properties test); the walls exchange it.
#[test]
#[ignore = "25 s in a release build, 14 min in debug: cargo test --release -p mechkit --features image --test billiards -- --ignored"]
fn billiards_100_disks_10_000_collisions() {
    // 35 s of motion give about 10,500 impacts
    let radius = 0.01;
    let collisions = disks_in_a_box(10, radius, &[1.0], 2.0, 777).run_elastic(radius, 5e-3, 35.0);
    assert!(collisions >= 10_000, "{collisions} impacts");
}
