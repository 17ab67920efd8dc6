//! Paths as URIs (RFC 8089, RFC 3986): what SARIF names a file by and
//! what an editor's server names other files by. A leaf: it knows paths
//! and bytes, nothing of programs.

use std::path::Path;

/// A path's bytes as the file system holds them: on Unix the name's own
/// bytes, which need not be UTF-8 (a `Kühl.MPF` saved in Latin-1), so that
/// a SARIF URI can name the very file; elsewhere its text (Windows names
/// are UTF-16, read as Unicode, an unpaired surrogate replaced).
#[cfg(unix)]
pub fn path_bytes(path: &Path) -> std::borrow::Cow<'_, [u8]> {
    use std::os::unix::ffi::OsStrExt;
    std::borrow::Cow::Borrowed(path.as_os_str().as_bytes())
}

#[cfg(not(unix))]
pub fn path_bytes(path: &Path) -> std::borrow::Cow<'_, [u8]> {
    match path.to_string_lossy() {
        std::borrow::Cow::Borrowed(text) => std::borrow::Cow::Borrowed(text.as_bytes()),
        std::borrow::Cow::Owned(text) => std::borrow::Cow::Owned(text.into_bytes()),
    }
}

/// Whether paths are Windows paths here: `\` separates their parts, and
/// they may begin with a drive (`C:\`) or a server (`\\server\share`).
pub const WINDOWS_PATHS: bool = cfg!(windows);

#[derive(Debug, PartialEq)]
pub enum Uri {
    Absolute(String),
    Relative(String),
}

/// A path as a URI (RFC 8089): `/a/b` as `file:///a/b`; with `windows`,
/// `\` read as `/`, `C:\CAM\PART.MPF` as `file:///C:/CAM/PART.MPF`,
/// `\\server\share\PART.MPF` as `file://server/share/PART.MPF`, and the
/// verbatim forms (`\\?\C:\...`, `\\?\UNC\server\...`) as the paths
/// they stand for. Anything else is a relative reference (`./` dropped).
/// Every byte but the unreserved characters and `/` is percent-encoded,
/// those of a name that is no UTF-8 as they are.
pub fn uri(path: &[u8], windows: bool) -> Uri {
    let mut path = path.to_vec();
    if windows {
        for byte in &mut path {
            if *byte == b'\\' {
                *byte = b'/';
            }
        }
        let unc = [&b"//?/UNC/"[..], b"//./UNC/"]
            .iter()
            .find_map(|prefix| path.strip_prefix(*prefix));
        let verbatim = [&b"//?/"[..], b"//./"]
            .iter()
            .find_map(|prefix| path.strip_prefix(*prefix));
        path = match (unc, verbatim) {
            (Some(server), _) => [&b"//"[..], server].concat(),
            (None, Some(local)) => local.to_vec(),
            (None, None) => path,
        };
        if let [drive, b':', rest @ ..] = &path[..] {
            if drive.is_ascii_alphabetic() && (rest.is_empty() || rest[0] == b'/') {
                return Uri::Absolute(format!(
                    "file:///{}:{}",
                    *drive as char,
                    percent_encoded(rest)
                ));
            }
        }
        if let Some(server) = path.strip_prefix(b"//") {
            return Uri::Absolute(format!("file://{}", percent_encoded(server)));
        }
    }
    if path.starts_with(b"/") {
        return Uri::Absolute(format!("file://{}", percent_encoded(&path)));
    }
    let relative = path.strip_prefix(b"./").unwrap_or(&path);
    Uri::Relative(percent_encoded(relative))
}

/// An absolute path as a `file` URI (an editor's server names other files
/// by it); `None` for a relative one.
pub fn file_uri(path: &std::path::Path) -> Option<String> {
    let bytes = path_bytes(path);
    match uri(&bytes, WINDOWS_PATHS) {
        Uri::Absolute(uri) => Some(uri),
        Uri::Relative(_) => None,
    }
}

/// RFC 3986: every byte but the unreserved characters and `/` as `%XX`.
fn percent_encoded(path: &[u8]) -> String {
    let mut out = String::with_capacity(path.len());
    for &byte in path {
        if byte.is_ascii_alphanumeric() || matches!(byte, b'-' | b'.' | b'_' | b'~' | b'/') {
            out.push(byte as char);
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn absolute(uri: &str) -> Uri {
        Uri::Absolute(uri.to_string())
    }

    fn relative(uri: &str) -> Uri {
        Uri::Relative(uri.to_string())
    }

    #[test]
    fn unix_paths_are_file_uris_or_relative_references() {
        assert_eq!(
            uri(b"/home/cam/OUT/PART 1.MPF", false),
            absolute("file:///home/cam/OUT/PART%201.MPF")
        );
        assert_eq!(uri(b"./OUT/PART.MPF", false), relative("OUT/PART.MPF"));
        assert_eq!(uri(b"OUT/PART.MPF", false), relative("OUT/PART.MPF"));
        // On Unix a backslash and a colon are a name's own characters.
        assert_eq!(uri(b"C:\\PART.MPF", false), relative("C%3A%5CPART.MPF"));
    }

    #[test]
    fn a_name_that_is_no_utf8_keeps_its_bytes() {
        // `Kühl.MPF` saved in Latin-1: ü is the byte 0xFC, not U+FFFD.
        assert_eq!(uri(b"K\xfchl.MPF", false), relative("K%FChl.MPF"));
        assert_eq!(
            uri("/cam/Kühl.MPF".as_bytes(), false),
            absolute("file:///cam/K%C3%BChl.MPF")
        );
    }

    #[test]
    fn windows_paths_are_file_uris_with_their_drive_or_server() {
        assert_eq!(
            uri(b"C:\\CAM\\OUT\\PART.MPF", true),
            absolute("file:///C:/CAM/OUT/PART.MPF")
        );
        assert_eq!(
            uri(b"d:/CAM/PART.MPF", true),
            absolute("file:///d:/CAM/PART.MPF")
        );
        assert_eq!(
            uri(b"\\\\server\\share\\OUT\\PART.MPF", true),
            absolute("file://server/share/OUT/PART.MPF")
        );
        assert_eq!(
            uri(b"\\\\?\\C:\\CAM\\PART.MPF", true),
            absolute("file:///C:/CAM/PART.MPF")
        );
        assert_eq!(
            uri(b"\\\\?\\UNC\\server\\share\\PART.MPF", true),
            absolute("file://server/share/PART.MPF")
        );
        assert_eq!(uri(b"OUT\\PART 2.MPF", true), relative("OUT/PART%202.MPF"));
        assert_eq!(uri(b".\\PART.MPF", true), relative("PART.MPF"));
    }
}
