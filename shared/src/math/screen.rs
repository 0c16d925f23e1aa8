//! Rectangles of pixels on the screen: where a flat shape seen by a camera can show, for a scissor
//! rectangle that keeps the rasterizer to it (lesson 16's doorways).

use glam::{Mat4, Vec2, Vec3};

/// A rectangle of whole pixels, from the top left, as wgpu's scissor rectangle takes it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ScreenRect {
    pub x: u32,
    pub y: u32,
    pub width: u32,
    pub height: u32,
}

impl ScreenRect {
    /// Every pixel of a target of `size`.
    pub fn whole((width, height): (u32, u32)) -> Self {
        Self {
            x: 0,
            y: 0,
            width,
            height,
        }
    }

    /// Every pixel a convex flat shape — its `corners` in the world, seen through `view_projection`
    /// — can cover on a target of `size`: the smallest rectangle around the corners' projections,
    /// a pixel wider each side (the GPU rounds its own way). The whole target where a corner lies
    /// behind the eye, whose projection wraps round through infinity.
    pub fn around(view_projection: Mat4, corners: &[Vec3], size: (u32, u32)) -> Self {
        let (width, height) = (size.0 as f32, size.1 as f32);
        let mut min = Vec2::splat(f32::INFINITY);
        let mut max = Vec2::splat(f32::NEG_INFINITY);
        for corner in corners {
            let clip = view_projection * corner.extend(1.0);
            if clip.w <= f32::EPSILON {
                return Self::whole(size);
            }
            // Normalised device coordinates to pixels: y runs down the screen.
            let ndc = clip.truncate().truncate() / clip.w;
            let pixel = Vec2::new((ndc.x + 1.0) * 0.5 * width, (1.0 - ndc.y) * 0.5 * height);
            min = min.min(pixel);
            max = max.max(pixel);
        }
        let left = (min.x.floor() - 1.0).clamp(0.0, width) as u32;
        let top = (min.y.floor() - 1.0).clamp(0.0, height) as u32;
        let right = (max.x.ceil() + 1.0).clamp(0.0, width) as u32;
        let bottom = (max.y.ceil() + 1.0).clamp(0.0, height) as u32;
        Self {
            x: left,
            y: top,
            width: right.saturating_sub(left),
            height: bottom.saturating_sub(top),
        }
    }

    /// The pixels in both: empty (no width or no height) where they do not meet.
    pub fn within(self, other: Self) -> Self {
        let (left, top) = (self.x.max(other.x), self.y.max(other.y));
        let right = (self.x + self.width).min(other.x + other.width);
        let bottom = (self.y + self.height).min(other.y + other.height);
        Self {
            x: left,
            y: top,
            width: right.saturating_sub(left),
            height: bottom.saturating_sub(top),
        }
    }

    /// Whether it holds pixel (x, y).
    pub fn contains(&self, (x, y): (u32, u32)) -> bool {
        x >= self.x && x - self.x < self.width && y >= self.y && y - self.y < self.height
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::room::camera::Camera;

    #[test]
    fn a_square_in_front_of_the_camera_covers_its_own_pixels() {
        // A 2 m square facing the camera 10 m away: its corners inside the rectangle, the
        // rectangle smaller than the screen.
        let camera = Camera {
            yaw: 0.0,
            pitch: 0.0,
            distance: 10.0,
        };
        let size = (640, 360);
        let view = camera.view_at(640.0 / 360.0).view_projection();
        let corners = [
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(1.0, 2.0, 0.0),
            Vec3::new(-1.0, 2.0, 0.0),
        ];
        let rect = ScreenRect::around(view, &corners, size);
        for corner in corners {
            let clip = view * corner.extend(1.0);
            let ndc = clip.truncate().truncate() / clip.w;
            let pixel = ((ndc.x + 1.0) * 320.0, (1.0 - ndc.y) * 180.0);
            assert!(
                rect.contains((pixel.0 as u32, pixel.1 as u32)),
                "{rect:?} {pixel:?}"
            );
        }
        assert!(rect.width < 640 && rect.height < 360, "{rect:?}");
    }

    #[test]
    fn a_shape_reaching_behind_the_eye_may_show_anywhere() {
        let camera = Camera {
            yaw: 0.0,
            pitch: 0.0,
            distance: 10.0,
        };
        let view = camera.view_at(1.0).view_projection();
        let corners = [Vec3::new(-1.0, 0.0, 0.0), Vec3::new(1.0, 0.0, 30.0)];
        assert_eq!(
            ScreenRect::around(view, &corners, (64, 64)),
            ScreenRect::whole((64, 64))
        );
    }

    #[test]
    fn rectangles_that_do_not_meet_have_nothing_within_both() {
        let a = ScreenRect::whole((10, 10));
        let b = ScreenRect {
            x: 20,
            y: 0,
            width: 5,
            height: 5,
        };
        assert_eq!(a.within(b).width, 0);
        let c = ScreenRect {
            x: 5,
            y: 5,
            width: 10,
            height: 10,
        };
        assert_eq!(
            a.within(c),
            ScreenRect {
                x: 5,
                y: 5,
                width: 5,
                height: 5
            }
        );
    }
}
