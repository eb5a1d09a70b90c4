//! Issue 19's neutral default material: an MDG grammar that never adds to
//! red, green or blue is drawn light grey (linear 0.8) instead of black, in
//! the glTF vertex colours and the PNG preview alike; a grammar that sets
//! any colour, black included, keeps exactly what it set (docs/mdg.md,
//! "Colour").

use crate::picture::Picture;
use rulemesh::export::{ExportOptions, Format, Instancing};
use rulemesh::lang::Language;
use rulemesh::pipeline::{render, RenderRequest};

/// The model as plain meshes (`instancing: flat`), whose vertex colours
/// `glb_colours` reads (an instanced mesh is white, its colour per instance:
/// tests/it/gpu_instancing.rs checks those against these).
fn bytes(source: &str, format: Format) -> Vec<u8> {
    let export_options = ExportOptions { instancing: Instancing::Flat, ..ExportOptions::default() };
    let req = RenderRequest { language: Some(Language::Mdg), format, export_options, ..RenderRequest::default() };
    render(source.as_bytes(), &req).unwrap_or_else(|e| panic!("{source}: {e}")).bytes
}

fn u32_at(b: &[u8], at: usize) -> usize {
    u32::from_le_bytes(b[at..at + 4].try_into().expect("4 bytes")) as usize
}

/// Every COLOR_0 value of every primitive in a GLB, as RGBA bytes.
fn glb_colours(glb: &[u8]) -> Vec<[u8; 4]> {
    assert_eq!(&glb[..4], b"glTF");
    let json_len = u32_at(glb, 12);
    let json: serde_json::Value = serde_json::from_slice(&glb[20..20 + json_len]).expect("json chunk");
    let bin = &glb[20 + json_len + 8..];
    let mut out = Vec::new();
    for mesh in json["meshes"].as_array().expect("meshes") {
        for prim in mesh["primitives"].as_array().expect("primitives") {
            let acc = &json["accessors"][prim["attributes"]["COLOR_0"].as_u64().expect("COLOR_0 accessor") as usize];
            assert_eq!((acc["componentType"].as_u64(), acc["type"].as_str()), (Some(5121), Some("VEC4")), "{acc}");
            let view = &json["bufferViews"][acc["bufferView"].as_u64().expect("view") as usize];
            let start = view["byteOffset"].as_u64().unwrap_or(0) as usize + acc["byteOffset"].as_u64().unwrap_or(0) as usize;
            let stride = view["byteStride"].as_u64().unwrap_or(4) as usize;
            for k in 0..acc["count"].as_u64().expect("count") as usize {
                let at = start + k * stride;
                out.push(bin[at..at + 4].try_into().expect("rgba"));
            }
        }
    }
    out
}

/// Linear 0.8 as a glTF normalised byte.
const GREY: u8 = 204;

#[test]
fn a_grammar_that_never_sets_a_colour_is_light_grey_everywhere() {
    // A box, a swept line and free vertices: every kind of geometry gets the grey.
    let plain = "startshape A\nrule A { BOX {} SPHERE { x 2 } MOVETO { x 4 } LINETO { x 6 } }\n";
    let colours = glb_colours(&bytes(plain, Format::Glb));
    assert!(!colours.is_empty());
    assert!(colours.iter().all(|&c| c == [GREY, GREY, GREY, 255]), "{:?}", colours.iter().find(|&&c| c != [GREY, GREY, GREY, 255]));
    let p = Picture::decode(&bytes(plain, Format::Png));
    assert!(p.coverage() > 0.01 && p.black_share() < 0.01, "coverage {}, black {}", p.coverage(), p.black_share());
    // Lit grey: every drawn pixel is neutral (no channel differs from another by more than a rounding).
    assert!(p.pixels().filter(|(_, _, q)| q[3] == 255).all(|(_, _, q)| q[0].abs_diff(q[1]) <= 1 && q[1].abs_diff(q[2]) <= 1));
    // Alpha alone is not a colour: translucent grey, not translucent black.
    let glass = glb_colours(&bytes("startshape A\nrule A { BOX { A -0.5 } }\n", Format::Glb));
    assert!(glass.iter().all(|&c| c == [GREY, GREY, GREY, 128]), "{:?}", glass.first());
}

#[test]
fn a_grammar_that_sets_a_colour_keeps_it_even_black() {
    // `R 0` sets red to 0: explicitly black, so black it stays, in glTF and in the preview.
    let black = "startshape A\nrule A { BOX { R 0 } }\n";
    let colours = glb_colours(&bytes(black, Format::Glb));
    assert!(!colours.is_empty() && colours.iter().all(|&c| c == [0, 0, 0, 255]), "{:?}", colours.first());
    let p = Picture::decode(&bytes(black, Format::Png));
    assert!(p.black_share() > 0.9, "black {}", p.black_share());
    // One coloured part keeps the uncoloured ones at the thesis's black too:
    // the default is the model's, not each primitive's.
    let mixed = glb_colours(&bytes("startshape A\nrule A { BOX {} SPHERE { x 2 G 1 } }\n", Format::Glb));
    assert!(mixed.contains(&[0, 0, 0, 255]) && mixed.contains(&[0, 255, 0, 255]), "{:?}", mixed.iter().collect::<std::collections::BTreeSet<_>>());
    // A colour in an iterator step counts as setting one.
    let stepped = glb_colours(&bytes("startshape A\nrule A { 2 * { x 2 B 0.5 } BOX {} }\n", Format::Glb));
    assert!(stepped.contains(&[0, 0, 128, 255]) && !stepped.contains(&[GREY, GREY, GREY, 255]), "{:?}", stepped.first());
}
