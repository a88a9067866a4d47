//! `umbrac render` options for the shadow technique (see
//! docs/performance.md): `--quality`, and the individual choices that
//! override it.

use crate::render::setup::{DepthFormat, Filter, Fit, Quality, Setup};

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum QualityArg {
    /// The tutorial's shadow: fixed +-4 light box, cube and floor in the
    /// shadow map, 3x3 PCF, 32-bit float depth.
    Tutorial,
    /// Less than half the tutorial's shadow error at no more frame time:
    /// light box fitted to the casters and the visible receivers, casters
    /// only in the shadow map, the hardware's 2x2 filter.
    Tuned,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FilterArg {
    /// One nearest-filtered compare.
    #[value(name = "1tap")]
    Tap1,
    /// One linear compare: the hardware's 2x2.
    #[value(name = "2x2")]
    Hw2x2,
    /// 3x3 linear compares (the tutorial's).
    #[value(name = "3x3")]
    Pcf3x3,
    /// 5x5 linear compares.
    #[value(name = "5x5")]
    Pcf5x5,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum FitArg {
    /// The tutorial's fixed +-4 box.
    Fixed,
    /// Fitted to the casters and the visible receivers.
    Tight,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum DepthArg {
    Depth16,
    Depth24plus,
    Depth32float,
}

/// The shadow-technique options.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct SetupArgs {
    /// A named shadow configuration; the options below override its parts.
    #[arg(long, value_enum)]
    pub quality: Option<QualityArg>,
    /// Shadow filter (a .das program is compiled with the matching -D PCF_TAPS_RADIUS).
    #[arg(long, value_enum)]
    pub filter: Option<FilterArg>,
    /// How the light's box is fitted.
    #[arg(long, value_enum)]
    pub fit: Option<FitArg>,
    /// Shadow map depth format.
    #[arg(long, value_enum)]
    pub depth_format: Option<DepthArg>,
    /// Draw only the shadow casters (the cube) into the shadow map.
    #[arg(long, num_args = 0..=1, default_missing_value = "true", value_name = "BOOL")]
    pub casters_only: Option<bool>,
}

impl SetupArgs {
    pub fn setup(&self) -> Setup {
        let mut s = Setup::of_quality(match self.quality {
            Some(QualityArg::Tuned) => Quality::Tuned,
            _ => Quality::Tutorial,
        });
        if let Some(f) = self.filter {
            s.shadow.filter = match f {
                FilterArg::Tap1 => Filter::Tap1,
                FilterArg::Hw2x2 => Filter::Hardware2x2,
                FilterArg::Pcf3x3 => Filter::Pcf3x3,
                FilterArg::Pcf5x5 => Filter::Pcf5x5,
            };
        }
        if let Some(f) = self.fit {
            s.shadow.fit = match f {
                FitArg::Fixed => Fit::Fixed,
                FitArg::Tight => Fit::Tight,
            };
        }
        if let Some(d) = self.depth_format {
            s.shadow.depth = match d {
                DepthArg::Depth16 => DepthFormat::Depth16,
                DepthArg::Depth24plus => DepthFormat::Depth24Plus,
                DepthArg::Depth32float => DepthFormat::Depth32Float,
            };
        }
        if let Some(c) = self.casters_only {
            s.shadow.casters_only = c;
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        args: SetupArgs,
    }

    #[test]
    fn quality_and_overrides() {
        let c = Cli::try_parse_from(["x"]).unwrap();
        assert_eq!(c.args.setup(), Setup::default());
        let c = Cli::try_parse_from(["x", "--quality", "tuned"]).unwrap();
        assert_eq!(c.args.setup(), Setup::tuned());
        let c = Cli::try_parse_from(["x", "--quality", "tuned", "--filter", "5x5", "--depth-format", "depth16", "--casters-only", "false"])
            .unwrap();
        let s = c.args.setup();
        assert_eq!((s.shadow.filter, s.shadow.depth, s.shadow.casters_only, s.shadow.fit), (Filter::Pcf5x5, DepthFormat::Depth16, false, Fit::Tight));
        let c = Cli::try_parse_from(["x", "--casters-only"]).unwrap();
        assert!(c.args.setup().shadow.casters_only);
    }
}
