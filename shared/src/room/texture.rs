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

/// Uploads an image with its full mipmap chain; returns a view of it.
pub fn upload(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    name: &str,
    image: &RgbaImage,
) -> wgpu::TextureView {
    let levels = mip_chain(image);
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some(name),
        size: wgpu::Extent3d {
            width: image.width(),
            height: image.height(),
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

/// The image and each half-size level below it, down to 1×1. Each texel of a level averages 2×2
/// texels of the one above in linear light (averaging sRGB numbers would darken the distance).
fn mip_chain(image: &RgbaImage) -> Vec<RgbaImage> {
    // Decoding is the inner loop: 256 values, so look them up.
    let decode: [f32; 256] = std::array::from_fn(|v| srgb_to_linear(v as u8));
    let mut levels = vec![image.clone()];
    while let Some(above) = levels.last().filter(|l| l.width() > 1 || l.height() > 1) {
        let (w, h) = ((above.width() / 2).max(1), (above.height() / 2).max(1));
        let next = RgbaImage::from_fn(w, h, |x, y| {
            let mut sum = [0.0f32; 4];
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let sx = (2 * x + dx).min(above.width() - 1);
                let sy = (2 * y + dy).min(above.height() - 1);
                let p = above.get_pixel(sx, sy).0;
                for c in 0..3 {
                    sum[c] += decode[p[c] as usize];
                }
                sum[3] += p[3] as f32 / 255.0;
            }
            let rgb = [0, 1, 2].map(|c| linear_to_srgb(sum[c] / 4.0));
            image::Rgba([rgb[0], rgb[1], rgb[2], (sum[3] / 4.0 * 255.0).round() as u8])
        });
        levels.push(next);
    }
    levels
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
        let levels = mip_chain(&image);
        assert_eq!(levels.len(), 3);
        assert_eq!(levels[2].dimensions(), (1, 1));
        assert_eq!(levels[1].get_pixel(0, 0).0, [188, 188, 188, 255]);
    }
}
