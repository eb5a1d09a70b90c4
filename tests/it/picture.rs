//! A decoded PNG preview and the pixel counts the preview and icon tests
//! assert on (coverage, drawn box, black share), shared so both read
//! pictures the same way.

#![allow(dead_code)]

/// A decoded preview: its side and RGBA8 pixels, and its text chunks.
pub struct Picture {
    pub size: usize,
    pub rgba: Vec<u8>,
    pub text: Vec<(String, String)>,
}

impl Picture {
    pub fn decode(bytes: &[u8]) -> Picture {
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n", "a PNG signature");
        let mut reader = png::Decoder::new(std::io::Cursor::new(bytes)).read_info().expect("PNG header");
        let mut buf = vec![0; reader.output_buffer_size().expect("size")];
        let frame = reader.next_frame(&mut buf).expect("PNG frame");
        assert_eq!((frame.color_type, frame.bit_depth), (png::ColorType::Rgba, png::BitDepth::Eight));
        assert_eq!(frame.width, frame.height);
        buf.truncate(frame.buffer_size());
        let text = reader.info().uncompressed_latin1_text.iter().map(|t| (t.keyword.clone(), t.text.clone())).collect();
        Picture { size: frame.width as usize, rgba: buf, text }
    }

    pub fn pixel(&self, x: usize, y: usize) -> [u8; 4] {
        let i = (y * self.size + x) * 4;
        [self.rgba[i], self.rgba[i + 1], self.rgba[i + 2], self.rgba[i + 3]]
    }

    pub fn pixels(&self) -> impl Iterator<Item = (usize, usize, [u8; 4])> + '_ {
        (0..self.size * self.size).map(|i| (i % self.size, i / self.size, self.pixel(i % self.size, i / self.size)))
    }

    /// The covered share of the picture: the sum of alpha over the pixel count.
    pub fn coverage(&self) -> f64 {
        self.pixels().map(|(_, _, p)| f64::from(p[3])).sum::<f64>() / 255.0 / (self.size * self.size) as f64
    }

    /// The bounding box of pixels with any coverage: (x0, y0, x1, y1), inclusive.
    pub fn drawn_box(&self) -> Option<(usize, usize, usize, usize)> {
        self.pixels().filter(|(_, _, p)| p[3] > 0).fold(None, |b, (x, y, _)| match b {
            None => Some((x, y, x, y)),
            Some((x0, y0, x1, y1)) => Some((x0.min(x), y0.min(y), x1.max(x), y1.max(y))),
        })
    }

    /// The share of the drawn (alpha-weighted) pixels that are pure black
    /// (no channel above 16 of 255; colours are straight, so a partly covered
    /// pixel has its surface's colour).
    pub fn black_share(&self) -> f64 {
        let weight = |p: &[u8; 4]| f64::from(p[3]);
        let drawn: Vec<[u8; 4]> = self.pixels().map(|(_, _, p)| p).filter(|p| p[3] > 0).collect();
        let black: f64 = drawn.iter().filter(|p| p[..3].iter().all(|&c| c <= 16)).map(weight).sum();
        black / drawn.iter().map(weight).sum::<f64>().max(1.0)
    }

    /// The 30° hue sectors that hold at least `min_share` of the fully
    /// covered pixels, counting only coloured ones (max − min channel ≥ 40):
    /// lighting changes a surface's brightness, not its hue, so a plant with
    /// brown stems and green leaves fills two sectors and a one-colour plant
    /// one.
    pub fn hue_sectors(&self, min_share: f64) -> Vec<usize> {
        let mut sectors = [0usize; 12];
        let mut opaque = 0usize;
        for (_, _, p) in self.pixels().filter(|(_, _, p)| p[3] == 255) {
            opaque += 1;
            let [r, g, b] = [p[0], p[1], p[2]].map(f64::from);
            let (max, min) = (r.max(g).max(b), r.min(g).min(b));
            if max - min < 40.0 {
                continue;
            }
            let h = if max == r {
                60.0 * ((g - b) / (max - min)).rem_euclid(6.0)
            } else if max == g {
                60.0 * ((b - r) / (max - min) + 2.0)
            } else {
                60.0 * ((r - g) / (max - min) + 4.0)
            };
            sectors[((h / 30.0) as usize).min(11)] += 1;
        }
        (0..12).filter(|&k| opaque > 0 && sectors[k] as f64 >= min_share * opaque as f64).collect()
    }
}
