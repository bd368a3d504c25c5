mod errors;
mod examples;
mod planar;
mod rigid;
mod run;
mod sweep;
