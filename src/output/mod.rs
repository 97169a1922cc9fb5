//! Outputs of a solved scene: figures (PNG and SVG), CSV tables, VTU files for ParaView.
//!
//! Library code here writes files and returns what it wrote; it never prints.
//! [`chart`] is the shared line-chart API every figure of the project draws with.

pub mod chart;
mod error;

pub use error::OutputError;
