//! Image comparison, the shadow masks the tests reason about, and PNG / GIF
//! output.

use std::path::Path;

use image::{Rgba, RgbaImage};

/// How two images differ. A pixel's difference is the largest absolute
/// difference of its R, G and B channels (0-255).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiffStats {
    /// Pixels compared (those not masked out).
    pub pixels: usize,
    /// Pixels whose difference exceeds the threshold.
    pub over: usize,
    /// `over / pixels`.
    pub fraction_over: f64,
    /// Largest difference.
    pub max: u8,
    /// Mean difference over the compared pixels.
    pub mean: f64,
}

impl std::fmt::Display for DiffStats {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} of {} pixels ({:.3}%) over the threshold, max {}, mean {:.3}",
            self.over,
            self.pixels,
            100.0 * self.fraction_over,
            self.max,
            self.mean
        )
    }
}

fn pixel_delta(a: &Rgba<u8>, b: &Rgba<u8>) -> u8 {
    (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0)
}

/// Compares two images of the same size.
pub fn diff(a: &RgbaImage, b: &RgbaImage, delta: u8) -> DiffStats {
    diff_masked(a, b, delta, None)
}

/// Compares two images, skipping pixels where `skip` is true.
pub fn diff_masked(a: &RgbaImage, b: &RgbaImage, delta: u8, skip: Option<&[bool]>) -> DiffStats {
    assert_eq!(a.dimensions(), b.dimensions(), "images differ in size");
    let (mut pixels, mut over, mut max, mut sum) = (0usize, 0usize, 0u8, 0u64);
    for (i, (pa, pb)) in a.pixels().zip(b.pixels()).enumerate() {
        if skip.is_some_and(|s| s[i]) {
            continue;
        }
        let d = pixel_delta(pa, pb);
        pixels += 1;
        sum += d as u64;
        max = max.max(d);
        if d > delta {
            over += 1;
        }
    }
    DiffStats {
        pixels,
        over,
        fraction_over: if pixels == 0 { 0.0 } else { over as f64 / pixels as f64 },
        max,
        mean: if pixels == 0 { 0.0 } else { sum as f64 / pixels as f64 },
    }
}

/// A visual diff: black where equal, brighter red the larger the difference,
/// blue where masked.
pub fn diff_image(a: &RgbaImage, b: &RgbaImage, skip: Option<&[bool]>) -> RgbaImage {
    let (w, h) = a.dimensions();
    RgbaImage::from_fn(w, h, |x, y| {
        let i = (y * w + x) as usize;
        if skip.is_some_and(|s| s[i]) {
            return Rgba([0, 0, 96, 255]);
        }
        let d = pixel_delta(a.get_pixel(x, y), b.get_pixel(x, y)) as u32;
        Rgba([(d * 4).min(255) as u8, 0, 0, 255])
    })
}

fn luma(p: &Rgba<u8>) -> f32 {
    0.2126 * p[0] as f32 + 0.7152 * p[1] as f32 + 0.0722 * p[2] as f32
}

/// Pixels in shadow: noticeably darker in the `final` image than in the
/// `lit` image of the same frame (the same scene with an empty shadow map,
/// or with no shadow rays). Both images must come from the same renderer.
pub fn shadow_mask(final_img: &RgbaImage, lit_img: &RgbaImage) -> Vec<bool> {
    assert_eq!(final_img.dimensions(), lit_img.dimensions());
    final_img.pixels().zip(lit_img.pixels()).map(|(f, l)| luma(l) - luma(f) > 24.0).collect()
}

/// Intersection over union of two masks (1.0 when both are empty).
pub fn iou(a: &[bool], b: &[bool]) -> f64 {
    let inter = a.iter().zip(b).filter(|(x, y)| **x && **y).count();
    let union = a.iter().zip(b).filter(|(x, y)| **x || **y).count();
    if union == 0 {
        1.0
    } else {
        inter as f64 / union as f64
    }
}

/// Centre of the set pixels of a mask `width` wide, in pixels (x right, y down).
pub fn centroid(mask: &[bool], width: u32) -> Option<(f64, f64)> {
    let (mut n, mut sx, mut sy) = (0usize, 0.0, 0.0);
    for (i, _) in mask.iter().enumerate().filter(|(_, m)| **m) {
        n += 1;
        sx += (i as u32 % width) as f64 + 0.5;
        sy += (i as u32 / width) as f64 + 0.5;
    }
    (n > 0).then(|| (sx / n as f64, sy / n as f64))
}

pub fn count(mask: &[bool]) -> usize {
    mask.iter().filter(|m| **m).count()
}

/// Greyscale view of a depth texture (little-endian f32 texels, top row
/// first): the nearest depth drawn is black, the farthest drawn is light
/// grey, and texels still at the cleared far plane (1.0) are white.
pub fn depth_to_grey(width: u32, height: u32, bytes: &[u8]) -> RgbaImage {
    let depths: Vec<f32> = bytes.chunks_exact(4).map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
    let drawn = depths.iter().copied().filter(|d| *d < 1.0);
    let lo = drawn.clone().fold(f32::INFINITY, f32::min);
    let hi = drawn.fold(f32::NEG_INFINITY, f32::max);
    let span = (hi - lo).max(1e-6);
    RgbaImage::from_fn(width, height, |x, y| {
        let d = depths[(y * width + x) as usize];
        let g = if d >= 1.0 { 255 } else { (((d - lo) / span) * 200.0).round().clamp(0.0, 200.0) as u8 };
        Rgba([g, g, g, 255])
    })
}

/// Writes a PNG, creating the parent directory. Atomically (a temporary
/// renamed over it): a viewer of the file, or `render --watch` failing
/// half-way, never leaves half a picture.
pub fn save_png(image: &RgbaImage, path: &Path) -> Result<(), String> {
    let mut png = Vec::new();
    image.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png).map_err(|e| format!("encoding {}: {e}", path.display()))?;
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = path.file_name().ok_or_else(|| format!("`{}` is not a file name", path.display()))?.to_string_lossy().into_owned();
    let a = crate::Artifact { file_name: name, target: None, entry: None, contents: png };
    crate::output::write_artifacts(dir, &[a]).map_err(|e| format!("writing {}: {e}", path.display()))
}

/// Writes an endlessly looping animated GIF at `fps` frames per second.
pub fn save_gif(frames: &[RgbaImage], fps: f32, path: &Path) -> Result<(), String> {
    use image::codecs::gif::{GifEncoder, Repeat};
    let file = std::fs::File::create(path).map_err(|e| format!("creating {}: {e}", path.display()))?;
    let mut enc = GifEncoder::new_with_speed(std::io::BufWriter::new(file), 10);
    enc.set_repeat(Repeat::Infinite).map_err(|e| format!("writing {}: {e}", path.display()))?;
    let delay_ms = (1000.0 / fps.max(0.01)).round() as u32;
    for f in frames {
        let frame = image::Frame::from_parts(f.clone(), 0, 0, image::Delay::from_numer_denom_ms(delay_ms, 1));
        enc.encode_frame(frame).map_err(|e| format!("writing {}: {e}", path.display()))?;
    }
    Ok(())
}

/// Side-by-side composition (for docs and debugging).
pub fn side_by_side(images: &[&RgbaImage]) -> RgbaImage {
    let h = images.iter().map(|i| i.height()).max().unwrap_or(0);
    let w: u32 = images.iter().map(|i| i.width()).sum();
    let mut out = RgbaImage::from_pixel(w, h, Rgba([0, 0, 0, 255]));
    let mut x0 = 0;
    for img in images {
        image::imageops::replace(&mut out, *img, x0 as i64, 0);
        x0 += img.width();
    }
    out
}

/// Height of the label bar [`labelled_strip`] puts above each image.
pub const LABEL_HEIGHT: u32 = 24;

/// A one-bit canvas embedded-graphics draws text into.
struct Mask {
    width: u32,
    height: u32,
    on: Vec<bool>,
}

impl embedded_graphics::geometry::OriginDimensions for Mask {
    fn size(&self) -> embedded_graphics::geometry::Size {
        embedded_graphics::geometry::Size::new(self.width, self.height)
    }
}

impl embedded_graphics::draw_target::DrawTarget for Mask {
    type Color = embedded_graphics::pixelcolor::BinaryColor;
    type Error = std::convert::Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = embedded_graphics::Pixel<Self::Color>>,
    {
        for embedded_graphics::Pixel(p, c) in pixels {
            if p.x >= 0 && p.y >= 0 && (p.x as u32) < self.width && (p.y as u32) < self.height && c.is_on() {
                self.on[(p.y as u32 * self.width + p.x as u32) as usize] = true;
            }
        }
        Ok(())
    }
}

/// `text` in white on a dark bar `width` x [`LABEL_HEIGHT`], in a built-in
/// 10 x 20 bitmap font (cut at the bar's right edge).
pub fn label(text: &str, width: u32) -> RgbaImage {
    use embedded_graphics::mono_font::{ascii::FONT_10X20, MonoTextStyle};
    use embedded_graphics::pixelcolor::BinaryColor;
    use embedded_graphics::prelude::*;
    use embedded_graphics::text::{Baseline, Text};
    let mut mask = Mask { width, height: LABEL_HEIGHT, on: vec![false; (width * LABEL_HEIGHT) as usize] };
    let style = MonoTextStyle::new(&FONT_10X20, BinaryColor::On);
    let Ok(_) = Text::with_baseline(text, Point::new(6, 2), style, Baseline::Top).draw(&mut mask);
    RgbaImage::from_fn(width, LABEL_HEIGHT, |x, y| {
        if mask.on[(y * width + x) as usize] {
            Rgba([255, 255, 255, 255])
        } else {
            Rgba([24, 24, 32, 255])
        }
    })
}

/// Images side by side, each under a bar with its name (the consumers
/// picture: `umbrac render --compare-backends` writes it as `OUT.all.png`).
pub fn labelled_strip(images: &[(&str, &RgbaImage)]) -> RgbaImage {
    let labelled: Vec<RgbaImage> = images
        .iter()
        .map(|(name, image)| {
            let mut out = RgbaImage::from_pixel(image.width(), image.height() + LABEL_HEIGHT, Rgba([0, 0, 0, 255]));
            image::imageops::replace(&mut out, &label(name, image.width()), 0, 0);
            image::imageops::replace(&mut out, *image, 0, LABEL_HEIGHT as i64);
            out
        })
        .collect();
    side_by_side(&labelled.iter().collect::<Vec<_>>())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn diff_counts_over_threshold() {
        let a = RgbaImage::from_pixel(4, 1, Rgba([10, 10, 10, 255]));
        let mut b = a.clone();
        b.put_pixel(0, 0, Rgba([20, 10, 10, 255]));
        b.put_pixel(1, 0, Rgba([13, 10, 10, 255]));
        let d = diff(&a, &b, 5);
        assert_eq!((d.over, d.max, d.pixels), (1, 10, 4));
        assert!((d.mean - 13.0 / 4.0).abs() < 1e-9);
        let d = diff_masked(&a, &b, 5, Some(&[true, false, false, false]));
        assert_eq!((d.over, d.pixels), (0, 3));
    }

    #[test]
    fn masks() {
        let a = [true, true, false, false];
        let b = [false, true, true, false];
        assert!((iou(&a, &b) - 1.0 / 3.0).abs() < 1e-9);
        assert_eq!(centroid(&a, 2), Some((1.0, 0.5)));
        assert_eq!(centroid(&[false; 4], 2), None);
    }

    #[test]
    fn labels_are_drawn_and_differ_by_name() {
        let a = label("gl330", 120);
        let b = label("gles300", 120);
        let white = |i: &RgbaImage| i.pixels().filter(|p| p[0] == 255).count();
        assert!(white(&a) > 40, "some text is drawn");
        assert_ne!(a, b);
        let img = RgbaImage::from_pixel(50, 10, Rgba([9, 9, 9, 255]));
        let strip = labelled_strip(&[("a", &img), ("b", &img)]);
        assert_eq!(strip.dimensions(), (100, 10 + LABEL_HEIGHT));
        assert_eq!(strip.get_pixel(75, LABEL_HEIGHT + 5), &Rgba([9, 9, 9, 255]));
    }
}
