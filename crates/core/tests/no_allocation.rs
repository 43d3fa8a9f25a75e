//! The thesis cubic basis in f64 evaluates without touching the heap: a
//! counting global allocator sees no allocation during the evaluation.
//!
//! A global allocator is an `unsafe` trait; this test file is the only place
//! the workspace allows `unsafe`, and it only forwards to `System`.
#![allow(unsafe_code)]

use std::alloc::{GlobalAlloc, Layout, System};
use std::hint::black_box;
use std::sync::atomic::{AtomicUsize, Ordering};

use trig_core::families::thesis;

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

// SAFETY: forwards every call unchanged to the system allocator.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        ALLOCATIONS.fetch_add(1, Ordering::SeqCst);
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn thesis_cubic_in_f64_does_not_allocate() {
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    let mut acc = 0.0;
    for i in 0..1000 {
        let theta = f64::from(i) * 1.5e-3;
        let (s, c) = theta.sin_cos();
        let b = thesis::cubic(black_box(&s), black_box(&c), black_box(&0.6));
        acc += b[0] + b[3];
    }
    let after = ALLOCATIONS.load(Ordering::SeqCst);
    black_box(acc);
    assert_eq!(after - before, 0);
}
