//! A flat 2D drawing: filled marks on a canvas in pixels, in drawing order.
//!
//! This is the part of a [`Model`](super::Model) that a 2D language makes
//! besides its flat 3D tiles: Context Free's picture (John Horigan, Mark
//! Lentczner and Chris Coyne, *Context Free*, cfdg 3.4) is a list of unit
//! primitives, each with an affine map to the canvas and a colour, drawn
//! one over the other. The `svg` writer prints it as cfdg's `-V` does and
//! the preview stage rasterises it for `png`; 3D formats ignore it and
//! write the scene. Data only, like the rest of the model: the front end
//! fills it, writers read it.

/// One unit primitive of a drawing, centred on the origin before its
/// transform: the shapes `SVGCanvas.cpp` writes and `aggCanvas.cpp` fills.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MarkKind {
    /// A circle of diameter 1.
    Circle,
    /// A square of side 1.
    Square,
    /// An equilateral triangle of side 1, centred on its centroid, apex up
    /// (before the y flip of the canvas): `(0, 0.57735)`, `(-0.5, -0.288675)`,
    /// `(0.5, -0.288675)` as cfdg's SVG `<defs>` writes it.
    Triangle,
    /// A path (Context Free's `path`): the drawing's [`Drawing::paths`]
    /// entry [`Mark::path`] names, in the mark's own units.
    Path,
    /// The whole canvas blended with the mark's colour (Context Free's
    /// `FILL` as a shape, `aggCanvas::primitive`'s `fillType`); an SVG has
    /// no element for it (`SVGCanvas::primitive` writes none).
    Fill,
}

impl MarkKind {
    /// The triangle's corners as cfdg's SVG writes them (`SVGCanvas.cpp`).
    pub const TRIANGLE: [(f64, f64); 3] = [(0.0, 0.57735), (-0.5, -0.288675), (0.5, -0.288675)];
}

/// One filled mark: a unit primitive, its map to canvas pixels and its colour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mark {
    /// Which primitive.
    pub kind: MarkKind,
    /// The map from the unit primitive to canvas pixels, y down, as SVG's
    /// `matrix(a b c d e f)`: `x' = a·x + c·y + e`, `y' = b·x + d·y + f`.
    pub matrix: [f64; 6],
    /// The same map as a raster picture places the mark, in the same
    /// convention. It differs where the language's own rasteriser does:
    /// Context Free centres its PNG canvas by whole pixels before the y
    /// flip (its SVG, by fractions after it) and grows every filled shape
    /// by a fraction of a pixel (`aggCanvas.cpp`, `adjustShapeSize`), so
    /// that the picture covers the pixels cfdg's does.
    pub raster: [f64; 6],
    /// Its fill, 8-bit sRGB with straight alpha (as cfdg quantises it).
    pub rgba: [u8; 4],
    /// For a [`MarkKind::Path`], its index in [`Drawing::paths`] (0 otherwise).
    pub path: u32,
}

/// One piece of a path outline, in the mark's own units (before its matrix).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Segment {
    /// Starts a new subpath at a point.
    MoveTo([f64; 2]),
    /// A straight line to a point.
    LineTo([f64; 2]),
    /// A quadratic Bézier curve: control point, end point.
    QuadTo([f64; 2], [f64; 2]),
    /// A cubic Bézier curve: two control points, end point.
    CubicTo([f64; 2], [f64; 2], [f64; 2]),
    /// Closes the subpath back to its start.
    Close,
}

/// How a path is painted: filled, or stroked with a pen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PathStyle {
    /// Filled, by the non-zero rule or the even-odd rule.
    Fill {
        /// The even-odd rule (else non-zero).
        even_odd: bool,
    },
    /// Stroked along its outline.
    Stroke {
        /// Pen width in the path's units (in pixels of the untransformed
        /// path scaled by the matrix's mean scale when `iso`).
        width: f64,
        /// The pen keeps its width whatever the matrix (Context Free's
        /// `iso`: the outline is transformed first, then stroked).
        iso: bool,
        /// Line join: 0 miter, 2 round, 3 bevel (AGG's numbers).
        join: u8,
        /// Line cap: 0 butt, 1 square, 2 round (AGG's numbers).
        cap: u8,
        /// Miter limit, in half widths.
        miter_limit: f64,
    },
}

/// A path's outline and paint, shared by every mark that draws it.
#[derive(Debug, Clone, PartialEq)]
pub struct DrawnPath {
    /// The outline.
    pub segments: Vec<Segment>,
    /// Fill or stroke.
    pub style: PathStyle,
}

/// Bytes a [`Mark`] takes in a drawing, charged to the memory budget by the
/// front end that adds it.
pub const MARK_BYTES: u64 = std::mem::size_of::<Mark>() as u64;

/// A 2D drawing: the canvas and its marks in drawing order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Drawing {
    /// Canvas width in pixels.
    pub width: u32,
    /// Canvas height in pixels.
    pub height: u32,
    /// The background, 8-bit sRGB with straight alpha.
    pub background: [u8; 4],
    /// The marks, first drawn first.
    pub marks: Vec<Mark>,
    /// The paths the [`MarkKind::Path`] marks draw.
    pub paths: Vec<DrawnPath>,
}

/// Bytes a path segment takes in a drawing (charged by the front end).
pub const SEGMENT_BYTES: u64 = std::mem::size_of::<Segment>() as u64;
