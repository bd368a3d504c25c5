mod errors;
mod files;
