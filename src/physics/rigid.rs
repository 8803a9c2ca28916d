//! Effective mass matrices and impact maps (document section 2): not built yet.
