//! The view file (`.v`), the animation file (`.a`) and the colour map
//! (`.map`) of a vlab object, read as cpfg reads them
//! (`AlgorithmicBotany/vlab`, `cpfg/interpret.c`, `InitializeParameters`
//! and the view-file reader; `cpfg/animparam.c`; manual §8.1–8.2). Only
//! what decides the geometry is kept: the angle, widths, colours, scale,
//! tropism, line style and the cut setting. Lines are `command: values`;
//! a command this reader does not know is skipped, as cpfg skips it.

/// How `F` and `G` are drawn (manual §8.1.5, `line style:`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineStyle {
    /// Flat lines `width` pixels wide (drawn here as tubes, a pixel a fixed
    /// fraction of the drawing's extent: `lower::PIXELS_ACROSS`).
    Pixel,
    /// Flat polygons `width` world units wide (drawn as tubes).
    Polygon,
    /// Cylinders `width` world units wide.
    Cylinder,
}

/// World units per pixel of width when lines are pixels, before the
/// drawing's extent is known (`lower` then takes a pixel as a fraction of it).
pub(crate) const PIXEL: f64 = 0.05;

/// What the view, animation and colour map files say.
#[derive(Debug, Clone, PartialEq)]
pub struct View {
    /// `angle increment:` (or 360 / `angle factor:`), degrees; default 45.
    pub angle: f64,
    /// `initial line width:`; default 1.
    pub width: f64,
    /// `line width increment:`; default 0.
    pub width_increment: f64,
    /// `initial color:`; default 128 (cpfg's `InitializeParameters`).
    pub colour: i64,
    /// `color increment:`; default 1.
    pub colour_increment: i64,
    /// `initial scale:`; default 1.
    pub scale: f64,
    /// `scale multiplier:`; default 1.
    pub scale_multiplier: f64,
    /// How lines are drawn.
    pub line_style: LineStyle,
    /// The first tropism's direction and initial elasticity.
    pub tropism: Option<([f64; 3], f64)>,
    /// `interpretation past %:`; default on.
    pub past_cut: bool,
    /// The colour map: 256 RGB entries in 0..=1 (`None`: the default palette).
    pub palette: Option<Vec<[f64; 3]>>,
    /// `last frame:` of the animation file, when positive.
    pub last_frame: Option<u32>,
    /// Files the view names (surfaces, contours, functions) that were not sent.
    pub missing: Vec<String>,
    /// The functions of `function:` and `function set:`, in order (ids from 1).
    pub functions: Vec<super::func::Function>,
    /// Whether the functions came from a gallery, whose names cpfg
    /// predefines as macros (`cpfg/generate.c`, `PreprocessLsystem`).
    pub gallery: bool,
    /// Files the view names that could not be read, with why.
    pub unreadable: Vec<String>,
}

impl Default for View {
    fn default() -> View {
        View {
            angle: 45.0,
            width: 1.0,
            width_increment: 0.0,
            colour: 128,
            colour_increment: 1,
            scale: 1.0,
            scale_multiplier: 1.0,
            line_style: LineStyle::Pixel,
            tropism: None,
            past_cut: true,
            palette: None,
            last_frame: None,
            missing: Vec::new(),
            functions: Vec::new(),
            gallery: false,
            unreadable: Vec::new(),
        }
    }
}

fn numbers(s: &str) -> Vec<f64> {
    s.split(|c: char| c.is_whitespace() || c == ',').filter_map(|w| w.parse::<f64>().ok()).collect()
}

/// Removes `/* … */` comments.
fn uncomment(text: &str) -> String {
    let mut out = String::new();
    let mut rest = text;
    while let Some(k) = rest.find("/*") {
        out.push_str(&rest[..k]);
        match rest[k + 2..].find("*/") {
            Some(e) => rest = &rest[k + 2 + e + 2..],
            None => rest = "",
        }
    }
    out.push_str(rest);
    out
}

impl View {
    /// Reads a view file; `file` gives a file it names, when it was sent.
    pub fn read(&mut self, text: &str, file: &dyn Fn(&str) -> Option<String>) {
        let exists = |n: &str| file(n).is_some();
        let text = uncomment(text);
        for line in text.lines() {
            let Some((cmd, rest)) = line.split_once(':') else { continue };
            let cmd = cmd.trim().to_ascii_lowercase();
            let rest = rest.trim();
            let n = numbers(rest);
            let first = n.first().copied();
            match cmd.as_str() {
                "angle increment" => self.angle = first.unwrap_or(self.angle),
                "angle factor" => {
                    if let Some(f) = first.filter(|f| *f != 0.0) {
                        self.angle = 360.0 / f;
                    }
                }
                "initial color" => self.colour = first.map_or(self.colour, |v| v as i64),
                "color increment" => self.colour_increment = first.map_or(self.colour_increment, |v| v as i64),
                "initial line width" => {
                    self.width = first.unwrap_or(self.width);
                    let style = rest.split_whitespace().nth(1).unwrap_or("");
                    if style.starts_with('s') {
                        self.line_style = LineStyle::Cylinder;
                    } else if style.starts_with('p') {
                        self.line_style = LineStyle::Pixel;
                    }
                }
                "line width increment" => self.width_increment = first.unwrap_or(self.width_increment),
                "initial scale" => self.scale = first.unwrap_or(self.scale),
                "scale multiplier" => self.scale_multiplier = first.unwrap_or(self.scale_multiplier),
                "line style" => {
                    self.line_style = match rest.split_whitespace().next().unwrap_or("") {
                        "polygon" => LineStyle::Polygon,
                        "cylinder" => LineStyle::Cylinder,
                        _ => LineStyle::Pixel,
                    }
                }
                "interpretation past %" => self.past_cut = !rest.starts_with("off"),
                "tropism direction" => {
                    if n.len() >= 3 {
                        let e = self.tropism.map_or(0.0, |t| t.1);
                        self.tropism = Some(([n[0], n[1], n[2]], e));
                    }
                }
                "initial elasticity" => {
                    let d = self.tropism.map_or([0.0, -1.0, 0.0], |t| t.0);
                    self.tropism = Some((d, first.unwrap_or(0.0)));
                }
                "tropism" if self.tropism.is_none() => self.tropism = tropism(rest),
                "function" | "function set" => {
                    let mut words = rest.split_whitespace();
                    let name = words.next().unwrap_or("");
                    let samples = words.next().and_then(|w| w.parse::<usize>().ok()).unwrap_or(0);
                    let Some(body) = file(name) else {
                        self.missing.push(name.to_string());
                        continue;
                    };
                    let read = if cmd == "function" { super::func::read_function(&body, samples).map(|f| vec![f]) } else { super::func::read_set(&body) };
                    match read {
                        Ok(fs) => {
                            self.gallery |= cmd == "function set";
                            self.functions.extend(fs);
                        }
                        Err(e) => self.unreadable.push(format!("{name}: {e}")),
                    }
                }
                "surface" | "contour" | "line" | "tsurface" | "background scene" => {
                    let words: Vec<&str> = rest.split(|c: char| c.is_whitespace() || c == ',').filter(|w| !w.is_empty()).collect();
                    let named = if matches!(cmd.as_str(), "surface" | "contour" | "line" | "tsurface") { words.get(1) } else { words.first() };
                    if let Some(f) = named {
                        if !exists(f) {
                            self.missing.push((*f).to_string());
                        }
                    }
                }
                _ => {}
            }
        }
    }

    /// Reads an animation file: only `last frame:` matters (manual §8.2).
    /// Any positive count a `u32` holds is kept, however large, as the
    /// L-system's own `derivation length:` is: the step budget, not this
    /// reader, refuses a derivation too long to run.
    pub(crate) fn read_animation(&mut self, text: &str) {
        for line in uncomment(text).lines() {
            if let Some((cmd, rest)) = line.split_once(':') {
                if cmd.trim().eq_ignore_ascii_case("last frame") {
                    if let Some(v) = numbers(rest).first().filter(|v| **v > 0.0 && **v <= f64::from(u32::MAX)) {
                        self.last_frame = Some(*v as u32);
                    }
                }
            }
        }
    }

    /// Reads a colour map: 256 entries of 3 bytes (palette's `.map`).
    pub(crate) fn read_map(&mut self, bytes: &[u8]) {
        if bytes.len() >= 768 {
            self.palette = Some(bytes[..768].chunks(3).map(|c| [c[0] as f64 / 255.0, c[1] as f64 / 255.0, c[2] as f64 / 255.0]).collect());
        }
    }

    /// The RGBA colour of colour index `i`: the map's entry, else the
    /// default palette (a ramp of 16 hues at 60 % saturation; index 0 black).
    pub fn rgba(&self, i: i64) -> [f64; 4] {
        let i = i.rem_euclid(256) as usize;
        if let Some(p) = &self.palette {
            let c = p[i];
            return [c[0], c[1], c[2], 1.0];
        }
        if i == 0 {
            return [0.0, 0.0, 0.0, 1.0];
        }
        let h = ((i - 1) % 16) as f64 / 16.0 * 6.0;
        let (s, v) = (0.6, 0.9);
        let f = h - h.floor();
        let (p, q, t) = (v * (1.0 - s), v * (1.0 - s * f), v * (1.0 - s * (1.0 - f)));
        let (r, g, b) = match h as u32 {
            0 => (v, t, p),
            1 => (q, v, p),
            2 => (p, v, t),
            3 => (p, q, v),
            4 => (t, p, v),
            _ => (v, p, q),
        };
        [r, g, b, 1.0]
    }
}

/// `tropism: T: x y z … E: e` (manual §8.1.8).
fn tropism(rest: &str) -> Option<([f64; 3], f64)> {
    let mut dir = None;
    let mut e = 0.0;
    let words: Vec<&str> = rest.split_whitespace().collect();
    for (k, w) in words.iter().enumerate() {
        let nums = |n: usize| words[k + 1..].iter().take(n).filter_map(|x| x.trim_matches(',').parse::<f64>().ok()).collect::<Vec<_>>();
        match w.trim_end_matches(':') {
            "T" => {
                let v = nums(3);
                if v.len() == 3 {
                    dir = Some([v[0], v[1], v[2]]);
                }
            }
            "E" => e = nums(1).first().copied().unwrap_or(0.0),
            _ => {}
        }
    }
    dir.map(|d| (d, e))
}
