//! Watching a run: every piece of trajectory and every event.

/// One piece of trajectory inside a mode: a step, or the part of it before an event.
pub struct Segment<'a, const N: usize> {
    /// Start time (s).
    pub t0: f64,
    /// End time (s).
    pub t1: f64,
    /// State at `t0`.
    pub y0: [f64; N],
    /// State at `t1`.
    pub y1: [f64; N],
    pub(super) eval: &'a dyn Fn(f64) -> [f64; N],
}

impl<const N: usize> Segment<'_, N> {
    /// The state at `t` in `[t0, t1]` (dense output or closed form).
    pub(crate) fn eval(&self, t: f64) -> [f64; N] {
        (self.eval)(t)
    }
}

/// Watches a run: every segment (accepted step) and every event.
pub trait Observer<M, const N: usize> {
    /// Called for every piece of trajectory, in time order.
    fn segment(&mut self, _mode: M, _seg: &Segment<'_, N>) {}
    /// Called at every event with the state before the reset and the next mode and
    /// state after it (`None` if the run stops).
    fn event(
        &mut self,
        _t_s: f64,
        _from: M,
        _guard: usize,
        _before: &[f64; N],
        _after: Option<(M, &[f64; N])>,
    ) {
    }
}

impl<M, const N: usize> Observer<M, N> for () {}
