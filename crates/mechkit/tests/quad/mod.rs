mod course;
mod orders;
mod samples;
