//! Writing outputs to disk atomically.
