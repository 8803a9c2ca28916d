//! What counts as locomotion (document section 1): not built yet.
