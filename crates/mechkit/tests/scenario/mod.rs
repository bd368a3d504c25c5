mod errors;
mod examples;
mod planar;
mod rigid;
mod run;
mod spatial;
mod spatial_joints;
mod sweep;
