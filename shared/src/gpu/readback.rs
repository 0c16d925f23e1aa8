//! Reading a buffer back from the GPU, one way for every runner: natively the GPU is waited for at
//! once; in the browser the page's event loop maps the buffer, and the future wakes then.

use std::future::Future;
use std::pin::Pin;
use std::sync::{Arc, Mutex};
use std::task::{Context as TaskContext, Poll, Waker};

use anyhow::{Context, Result};

/// The bytes of `buffer` (`MAP_READ`), once the GPU has written them.
pub async fn read_buffer(device: &wgpu::Device, buffer: &wgpu::Buffer) -> Result<Vec<u8>> {
    let slice = buffer.slice(..);
    let mapping = Mapping::default();
    let done = mapping.0.clone();
    slice.map_async(wgpu::MapMode::Read, move |result| {
        let mut done = done.lock().unwrap_or_else(|e| e.into_inner());
        done.result = Some(result);
        if let Some(waker) = done.waker.take() {
            waker.wake();
        }
    });
    #[cfg(not(target_arch = "wasm32"))]
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .context("waiting for the GPU failed")?;
    #[cfg(target_arch = "wasm32")]
    let _ = device;
    mapping.await.context("reading back from the GPU failed")?;
    let mapped = slice
        .get_mapped_range()
        .context("reading back from the GPU failed")?;
    Ok(mapped.to_vec())
}

/// A buffer being mapped: ready when wgpu calls back.
#[derive(Default)]
struct Mapping(Arc<Mutex<Mapped>>);

#[derive(Default)]
struct Mapped {
    result: Option<Result<(), wgpu::BufferAsyncError>>,
    waker: Option<Waker>,
}

impl Future for Mapping {
    type Output = Result<(), wgpu::BufferAsyncError>;

    fn poll(self: Pin<&mut Self>, context: &mut TaskContext<'_>) -> Poll<Self::Output> {
        let mut mapped = self.0.lock().unwrap_or_else(|e| e.into_inner());
        match mapped.result.take() {
            Some(result) => Poll::Ready(result),
            None => {
                mapped.waker = Some(context.waker().clone());
                Poll::Pending
            }
        }
    }
}
