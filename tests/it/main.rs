//! Integration tests: the CLI and the library pipeline, checked with real
//! tools (the Khronos glTF Validator, admesh, GNU time). Run them through
//! `scripts/test`, which installs those tools.

mod common;
mod serve_child;
mod picture;

mod cfdg;
mod cfdg_limits;
mod cfdg_memo;
mod cfdg_pictures;
mod cfdg_examples;
mod cli;
mod c_decoder;
mod c_scene;
mod camera;
mod animation;
mod compact;
mod counts;
mod deadline;
mod default_colour;
mod directives;
mod etol;
mod determinism;
mod docs;
mod eisen;
mod formats;
mod gallery;
mod golden;
mod gpu_instancing;
mod grammars;
mod hostile;
mod icons;
mod instancing;
mod invariants;
mod lines;
mod winding;
mod workspace;
mod lsystem;
mod mdg_hierarchy;
mod modifiers;
mod preview;
mod provenance;
mod print;
mod print_memory;
mod scene;
mod scene_checksum;
mod selectors;
mod sheet;
mod ssfidelity;
mod strips;
mod unigrafix;
mod usdz;
mod scaleout;
mod service;
mod harden;
mod observe;
