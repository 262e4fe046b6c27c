//! An experiment series' results out of the app: its CSV table and its figure, through
//! the file dialog (in the browser, the table downloads; figures are the desktop's).

use crate::App;
#[cfg(not(target_arch = "wasm32"))]
use crate::files::Purpose;
use crate::i18n::tr;
use crate::{experiments, picture};

impl App {
    /// The name of the selected particle, if a particle is selected.
    pub(crate) fn selected_particle_name(&self) -> Option<String> {
        match self.selection {
            Some(crate::canvas::Selection::Particle(i)) => self
                .document
                .scene()
                .particles
                .get(i)
                .map(|p| p.name.clone()),
            _ => None,
        }
    }

    /// Exports series `index`'s results: as CSV (`None`) or as a figure.
    pub(crate) fn export_experiment(&mut self, index: usize, format: Option<picture::Format>) {
        let Some(Some(results)) = self.experiments.results.get(index) else {
            self.notify(tr("notice-nothing-to-export"));
            return;
        };
        match format {
            None => {
                self.table_ready = Some(experiments::to_csv(results));
                #[cfg(not(target_arch = "wasm32"))]
                self.files.ask(Purpose::ExportTable, None, "series.csv");
                #[cfg(target_arch = "wasm32")]
                self.save_table("series.csv");
            }
            #[cfg(not(target_arch = "wasm32"))]
            Some(format) => {
                match (
                    crate::figure::series(self.document.scene(), results, format),
                    format,
                ) {
                    (Ok(bytes), picture::Format::Png) => {
                        self.picture_ready = Some(bytes);
                        self.files.ask(Purpose::ExportPng, None, "series.png");
                    }
                    (Ok(bytes), picture::Format::Svg) => {
                        self.svg_ready = Some(bytes);
                        self.files.ask(Purpose::ExportSvg, None, "series.svg");
                    }
                    (Err(message), _) => self.notify(message),
                }
            }
            #[cfg(target_arch = "wasm32")]
            Some(_) => {}
        }
    }

    /// Writes the CSV table waiting to `path` (in the browser: downloads it).
    pub(crate) fn save_table(&mut self, path: &str) {
        let Some(text) = self.table_ready.take() else {
            return;
        };
        let rows = text.lines().count().saturating_sub(1);
        self.write_table(path, &text, rows);
    }
}
