//! The files an animation is written as.

use std::fmt;

/// An animation file's format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum AnimationFormat {
    /// An animated GIF (looping).
    Gif,
    /// An H.264 MP4 video, made by ffmpeg.
    Mp4,
    /// One self-contained HTML file that plays it, with play/pause and a time slider.
    Html,
}

impl AnimationFormat {
    /// Every format.
    pub const ALL: [AnimationFormat; 3] = [Self::Gif, Self::Mp4, Self::Html];

    /// By name: `gif`, `mp4` or `html`, any case.
    pub fn parse(text: &str) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|f| f.extension().eq_ignore_ascii_case(text.trim()))
    }

    /// The file extension, also its name.
    pub fn extension(self) -> &'static str {
        match self {
            Self::Gif => "gif",
            Self::Mp4 => "mp4",
            Self::Html => "html",
        }
    }

    /// The file an animation of this format is written to in an output directory:
    /// `animation.gif`.
    pub fn file_name(self) -> String {
        format!("animation.{}", self.extension())
    }
}

impl fmt::Display for AnimationFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.extension())
    }
}
