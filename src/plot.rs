//! The one figure style: not built yet.
