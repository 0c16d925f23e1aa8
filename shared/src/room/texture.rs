//! Textures: PNG files through `image`, with a mipmap chain filtered in linear light, on the GPU as sRGB.

#[cfg(not(target_arch = "wasm32"))]
use std::path::Path;

#[cfg(not(target_arch = "wasm32"))]
use anyhow::Context;
use anyhow::Result;
use image::RgbaImage;

use crate::gpu::{linear_to_srgb, srgb_to_linear};

/// The format of every colour texture: the PNGs hold sRGB-encoded colours.
pub const TEXTURE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// Reads a PNG file into RGBA8.
#[cfg(not(target_arch = "wasm32"))]
pub fn load_png(path: &Path) -> Result<RgbaImage> {
    let shown = path.display();
    let bytes = std::fs::read(path).with_context(|| format!("cannot read texture `{shown}`"))?;
    decode_png(&shown.to_string(), &bytes)
}

/// Decodes a PNG file's bytes into RGBA8; `name` names it in errors.
pub fn decode_png(name: &str, bytes: &[u8]) -> Result<RgbaImage> {
    let image = image::load_from_memory_with_format(bytes, image::ImageFormat::Png)
        .map_err(|error| anyhow::anyhow!("texture `{name}` is not a valid PNG: {error}"))?;
    Ok(image.to_rgba8())
}

/// A picture with its mipmap chain: the picture, then each half-size level below it, down to 1×1.
/// Made when the picture is decoded (on the assets' own thread at start-up, while the GPU opens).
#[derive(Debug, Clone)]
pub struct Mipmapped {
    pub levels: Vec<RgbaImage>,
}

impl Mipmapped {
    /// The picture with its chain. Each texel of a level averages 2×2 texels of the one above in
    /// linear light (averaging sRGB numbers would darken the distance).
    pub fn new(image: RgbaImage) -> Self {
        // Decoding is the inner loop: 256 values, so look them up.
        let decode: [f32; 256] = std::array::from_fn(|v| srgb_to_linear(v as u8));
        let mut levels = vec![image];
        while let Some(above) = levels.last().filter(|l| l.width() > 1 || l.height() > 1) {
            levels.push(half_size(above, &decode));
        }
        Self { levels }
    }
}

/// The level below `above`: each texel the linear-light average of the 2×2 above it (clamped at an
/// odd edge). Read from the raw bytes: a debug build spends its start-up here otherwise.
fn half_size(above: &RgbaImage, decode: &[f32; 256]) -> RgbaImage {
    let (width, height) = above.dimensions();
    let (w, h) = ((width / 2).max(1), (height / 2).max(1));
    let raw = above.as_raw();
    let texel = |x: u32, y: u32| {
        let i = 4 * (y.min(height - 1) as usize * width as usize + x.min(width - 1) as usize);
        &raw[i..i + 4]
    };
    let mut texels = Vec::with_capacity(4 * w as usize * h as usize);
    for y in 0..h {
        for x in 0..w {
            let mut sum = [0.0f32; 4];
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let p = texel(2 * x + dx, 2 * y + dy);
                for c in 0..3 {
                    sum[c] += decode[p[c] as usize];
                }
                sum[3] += p[3] as f32 / 255.0;
            }
            let rgb = [0, 1, 2].map(|c| linear_to_srgb(sum[c] / 4.0));
            texels.extend_from_slice(&rgb);
            texels.push((sum[3] / 4.0 * 255.0).round() as u8);
        }
    }
    RgbaImage::from_raw(w, h, texels).expect("four bytes per texel")
}

/// Uploads a picture with its mipmap chain; returns a view of it.
pub fn upload(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    name: &str,
    picture: &Mipmapped,
) -> wgpu::TextureView {
    let levels = &picture.levels;
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some(name),
        size: wgpu::Extent3d {
            width: levels[0].width(),
            height: levels[0].height(),
            depth_or_array_layers: 1,
        },
        mip_level_count: levels.len() as u32,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: TEXTURE_FORMAT,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for (level, pixels) in levels.iter().enumerate() {
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &texture,
                mip_level: level as u32,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            pixels.as_raw(),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(4 * pixels.width()),
                rows_per_image: None,
            },
            wgpu::Extent3d {
                width: pixels.width(),
                height: pixels.height(),
                depth_or_array_layers: 1,
            },
        );
    }
    texture.create_view(&wgpu::TextureViewDescriptor {
        label: Some(&format!("{name} view")),
        ..Default::default()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mip_chain_ends_at_one_texel_and_averages_in_linear_light() {
        // Black and white stripes average to linear 0.5, which is sRGB 188, not 128.
        let image = RgbaImage::from_fn(4, 2, |x, _| {
            let v = if x % 2 == 0 { 0 } else { 255 };
            image::Rgba([v, v, v, 255])
        });
        let levels = Mipmapped::new(image).levels;
        assert_eq!(levels.len(), 3);
        assert_eq!(levels[2].dimensions(), (1, 1));
        assert_eq!(levels[1].get_pixel(0, 0).0, [188, 188, 188, 255]);
    }
}
