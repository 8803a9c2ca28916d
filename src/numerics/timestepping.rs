//! Moreau-Jean time-stepping: not built yet.
