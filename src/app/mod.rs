//! See README.md (Architecture).
