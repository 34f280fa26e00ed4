//! The thread pools of `Mesh.buoyancy_batch(threads=n)`: one per size, built on first use and
//! kept for later calls.

use std::sync::{Arc, Mutex};

use pyo3::prelude::*;

use crate::errors::arg_error;

/// Thread pools by size.
static POOLS: Mutex<Vec<(usize, Arc<rayon::ThreadPool>)>> = Mutex::new(Vec::new());

/// The pool of `threads` threads (at least 1), built on first use.
pub fn pool(threads: usize) -> PyResult<Arc<rayon::ThreadPool>> {
    if threads == 0 {
        return Err(arg_error("threads", "must be at least 1"));
    }
    let mut pools = POOLS.lock().unwrap_or_else(|p| p.into_inner());
    if let Some((_, p)) = pools.iter().find(|(n, _)| *n == threads) {
        return Ok(p.clone());
    }
    let p = Arc::new(
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| arg_error("threads", e))?,
    );
    pools.push((threads, p.clone()));
    Ok(p)
}
