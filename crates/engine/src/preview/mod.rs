//! The preview stage: meshes → one RGBA picture, drawn on the CPU (no GPU,
//! no browser), so phone apps and the print backend can show a model where
//! they cannot run a 3D viewer. `format=png` runs it after meshing (or
//! printing); [`crate::export::png`] then encodes the picture.
//!
//! The stage is split by job: [`camera`] (the view directions and the
//! outlier-robust framing rule), [`shade`] (key, fill and rim light on the
//! vertex colours), [`closed`] (whether a mesh is a closed solid, whose back
//! faces need not be drawn), [`raster`] (a fixed-point, supersampled
//! triangle rasteriser with a depth buffer). `docs/preview.md` states the framing and
//! lighting rules.
//!
//! Determinism: every float is an IEEE basic operation in a fixed order (or
//! `libm`), coverage and interpolation in the rasteriser are integer, and
//! nothing runs on more than one thread, so the same meshes and options give
//! the same pixels on every run and machine.

pub mod camera;
pub mod closed;
pub mod drawing;
pub mod raster;
pub mod shade;
pub mod sheet;

use crate::core::budget::{Budget, LimitExceeded};
use crate::geom::NamedMesh;

/// Smallest picture side, in pixels.
pub(crate) const MIN_SIZE: u32 = 16;
/// Largest picture side, in pixels (2048² RGBA is 16 MiB, drawn in bands).
pub const MAX_SIZE: u32 = 2048;
/// The picture side when the request names none: a phone icon's.
pub(crate) const DEFAULT_SIZE: u32 = 256;

/// Where the camera looks from. All views are orthographic, with +Y up
/// (glTF's convention, which every exporter writes).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum View {
    /// From the front, 30° to the right and 20° above: the usual product
    /// shot, which shows three faces of a box with one dominant.
    #[default]
    ThreeQuarter,
    /// Straight at the front (from +Z).
    Front,
    /// Straight down (from +Y), the front at the bottom of the picture.
    Top,
    /// The isometric view: 45° round and 35.26° above, all three axes equally foreshortened.
    Iso,
}

impl crate::core::Choice for View {
    const ALL: &'static [Self] = &View::ALL;
    fn name(self) -> &'static str {
        View::name(self)
    }
}

impl View {
    /// Every view, in the order their names are listed in errors.
    pub const ALL: [View; 4] = [View::ThreeQuarter, View::Front, View::Top, View::Iso];

    /// The view's request name (`three-quarter`, `front`, `top`, `iso`), the
    /// one spelling of requests, the cache key and errors.
    pub fn name(self) -> &'static str {
        match self {
            View::ThreeQuarter => "three-quarter",
            View::Front => "front",
            View::Top => "top",
            View::Iso => "iso",
        }
    }

    /// Reads a view's request name.
    pub fn from_name(name: &str) -> Option<View> {
        View::ALL.into_iter().find(|v| v.name().eq_ignore_ascii_case(name.trim()))
    }
}

/// What a preview looks like: its size, view and background. Part of the
/// cache key of a `png` request (and of nothing else).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct PreviewOptions {
    /// Width and height in pixels ([`MIN_SIZE`]..=[`MAX_SIZE`]).
    pub size: u32,
    /// The camera's direction.
    pub view: View,
    /// An opaque background colour (sRGB); `None` is transparent, so an app
    /// can put the icon on its own background.
    pub background: Option<[u8; 3]>,
}

impl Default for PreviewOptions {
    fn default() -> Self {
        PreviewOptions { size: DEFAULT_SIZE, view: View::default(), background: None }
    }
}

impl PreviewOptions {
    /// Checks the options before any work, with a message for the caller.
    pub fn validate(&self) -> Result<(), String> {
        if !(MIN_SIZE..=MAX_SIZE).contains(&self.size) {
            return Err(format!("size must be in {MIN_SIZE}..={MAX_SIZE} pixels, got {}", self.size));
        }
        Ok(())
    }
}

/// Reads a background value: `transparent` (or empty), or an sRGB colour as
/// `#rrggbb` / `rrggbb`.
pub fn parse_background(text: &str) -> Result<Option<[u8; 3]>, String> {
    let t = text.trim();
    if t.is_empty() || t.eq_ignore_ascii_case("transparent") {
        return Ok(None);
    }
    let hex = t.strip_prefix('#').unwrap_or(t);
    let bad = || format!("background must be `transparent` or a colour `#rrggbb`, got `{text}`");
    if hex.len() != 6 || !hex.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(bad());
    }
    let byte = |i: usize| u8::from_str_radix(&hex[i..i + 2], 16).map_err(|_| bad());
    Ok(Some([byte(0)?, byte(2)?, byte(4)?]))
}

/// The spelling of a background in the cache key and docs: `transparent` or `#rrggbb`.
pub(crate) fn background_name(bg: Option<[u8; 3]>) -> String {
    match bg {
        None => "transparent".into(),
        Some([r, g, b]) => format!("#{r:02x}{g:02x}{b:02x}"),
    }
}

/// A drawn picture: `size`×`height` pixels, RGBA8 in sRGB with straight
/// (not premultiplied) alpha, rows top to bottom, as PNG stores them.
/// Square (`height == size`) except for a 2D drawing whose canvas is not:
/// a tiled or frieze CFDG design is framed to its tile, as cfdg frames it
/// (`renderimpl.cpp` `initBounds`), so its picture is the tile's shape.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub size: u32,
    /// Height in pixels.
    pub height: u32,
    /// `size * height * 4` bytes.
    pub rgba: Vec<u8>,
}

/// Why a preview could not be drawn.
#[derive(Debug, thiserror::Error)]
pub enum PreviewError {
    /// A limit ran out while drawing (steps for pixels × triangles, memory
    /// for the framebuffer, the deadline).
    #[error(transparent)]
    Limit(#[from] LimitExceeded),
    /// The options are out of range.
    #[error("invalid preview options: {0}")]
    BadOptions(String),
}

/// Draws `meshes` as the options say, charging the budget for the
/// framebuffer's memory (reserved before it is allocated, released after)
/// and for the pixels × triangles rasterised (see [`raster`]).
pub fn render(meshes: &[NamedMesh], options: &PreviewOptions, budget: &mut Budget) -> Result<Image, PreviewError> {
    options.validate().map_err(PreviewError::BadOptions)?;
    let vertex_bytes: u64 = meshes.iter().map(|m| m.mesh.positions.len() as u64 * raster::VERTEX_BYTES).sum();
    budget.reserve_memory(vertex_bytes)?;
    let image = draw(meshes, options, budget);
    budget.release_memory(vertex_bytes);
    image
}

/// [`render`] once the vertices' memory is reserved: the closed-solid test,
/// the framing, the projection and the raster, each looking at the
/// deadline (the first three are one pass over every triangle or vertex,
/// a quarter of a second each for millions).
fn draw(meshes: &[NamedMesh], options: &PreviewOptions, budget: &mut Budget) -> Result<Image, PreviewError> {
    let watch = budget.deadline_stop();
    let stop = || watch.stop();
    // Which meshes are closed solids, their back faces culled (one linear pass each).
    let cull = meshes.iter().map(|m| closed::closed_outward_until(&m.mesh, &stop)).collect::<Option<Vec<bool>>>().ok_or_else(|| watch.error())?;
    let frame = camera::Framing::of(meshes, options.view, options.size, raster::samples_per_axis(options.size));
    let lights = shade::Lights::default();
    let vertices = meshes.iter().map(|m| raster::project(&m.mesh, &frame, &lights, &stop)).collect::<Option<Vec<_>>>().ok_or_else(|| watch.error())?;
    Ok(raster::draw(meshes, &vertices, &cull, options, budget)?)
}
