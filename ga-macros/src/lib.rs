//! Proc-macro generating blade-sparse, straight-line geometric-algebra types.
