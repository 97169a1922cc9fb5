//! What a scene's preset adds to the one run folder ([`crate::generic::outputs`]): its own
//! figures and tables, its columns of `steps.csv`, the README's lines for them. The plate-insert
//! preset's post-processor (`crate::plate_insert::outputs`) is one; a plain generic scene has none.

use super::{OutputDir, OutputError};

/// A preset's files in a run folder, written by the one writer of every scene
/// (`crate::generic::outputs::finish_outputs`) after its own.
pub trait PresetFiles {
    /// Writes the preset's own files into `out`; a figure that cannot be drawn is noted in
    /// `skipped` (see `crate::output::figure`).
    ///
    /// # Errors
    /// [`OutputError`] naming the first file that could not be written.
    fn write(&self, out: &mut OutputDir, skipped: &mut Vec<String>) -> Result<(), OutputError>;

    /// Whether the preset draws every scene's figure `stem` (`history`, ...) itself, under the same
    /// name: the paper's `history` is l(w), b(w) (its figure 4), as it always was.
    fn replaces(&self, stem: &str) -> bool;

    /// The preset's columns of `steps.csv`: their names, and one row of values per step (empty
    /// where a value does not exist).
    fn step_columns(&self) -> (Vec<&'static str>, Vec<Vec<String>>);

    /// What the file `name` holds when it is the preset's (or when the preset describes a shared
    /// file otherwise, e.g. the time of `steps.pvd`); `None` for the others.
    fn describe(&self, name: &str) -> Option<&'static str>;

    /// The README's text after the list of files: the preset's units and its tables' columns.
    fn readme_notes(&self) -> String;
}
