// Copyright © 2026 The µCAD authors <info@microcad.xyz>
// SPDX-License-Identifier: AGPL-3.0-or-later
//
// rulemesh: builds the vendored Manifold 3.5.4 (no glm: Manifold has used its
// own linalg.h since 3.0) as a static library, serial and without downloads,
// then the cxx bridge against its headers (vendor/manifold-rs/PATCHES.md).

use cmake::Config;

fn main() {
    use std::env;

    // Skip building the library when building documentation
    if env::var("DOCS_RS").is_ok() {
        return;
    }

    let out_dir = env::var("OUT_DIR").unwrap();

    env::set_var("CMAKE_GENERATOR", "Ninja");
    env::set_var("CMAKE_BUILD_TYPE", "Release");

    let cxxflags = if cfg!(windows) { "/EHsc" } else { "" };

    Config::new("manifold")
        .cxxflag(cxxflags) //  MSVC flag to enable exception handling
        .define("CMAKE_BUILD_TYPE", "Release")
        .define("CMAKE_INSTALL_LIBDIR", "lib")
        .define("BUILD_SHARED_LIBS", "OFF")
        // Only the 3D library: no CrossSection (it needs Clipper2), no C,
        // Python or JS bindings, no tests, samples or extras.
        .define("MANIFOLD_CROSS_SECTION", "OFF")
        .define("MANIFOLD_CBIND", "OFF")
        .define("MANIFOLD_PYBIND", "OFF")
        .define("MANIFOLD_JSBIND", "OFF")
        .define("MANIFOLD_TEST", "OFF")
        .define("BUILD_TESTING", "OFF")
        // Serial (no TBB): one thread per union, and the same result
        // whatever the machine's core count.
        .define("MANIFOLD_PAR", "OFF")
        // Never fetch a dependency from the network.
        .define("MANIFOLD_DOWNLOADS", "OFF")
        .define("MANIFOLD_DEBUG", "OFF")
        .build();

    cxx_build::bridge("src/lib.rs")
        .std("c++17")
        .file("src/manifold_rs.cpp")
        .include("./src")
        .include("./manifold/include")
        .include(format!("{out_dir}/include"))
        .define("MANIFOLD_PAR", "-1")
        .compile("manifold_rs");

    println!("cargo:rustc-link-search={out_dir}/lib");
    println!("cargo:rustc-link-lib=static=manifold");

    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-changed=src/lib.rs");
    println!("cargo:rerun-if-changed=src/manifold_rs.h");
    println!("cargo:rerun-if-changed=src/manifold_rs.cpp");
    println!("cargo:rerun-if-changed=manifold");
}
