pub mod disks;
mod impacts;
mod properties;
