//! `umbrac preview` started on a free port, stopped when dropped.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::{Child, Command, Stdio};

pub struct PreviewServer {
    child: Child,
    pub port: u16,
}

impl PreviewServer {
    /// Starts `umbrac preview FILE --port 0` and reads the URL it prints.
    pub fn start(file: &Path) -> PreviewServer {
        Self::start_with(file, &[])
    }

    /// [`Self::start`] with more arguments (`--playground DIR`).
    pub fn start_with(file: &Path, more: &[&std::ffi::OsStr]) -> PreviewServer {
        let mut child = Command::new(env!("CARGO_BIN_EXE_umbrac"))
            .args(["preview", "--port", "0"])
            .args(more)
            .arg(file)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("umbrac starts");
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap()).read_line(&mut line).expect("umbrac prints the URL");
        let port = line
            .trim()
            .strip_suffix('/')
            .and_then(|l| l.rsplit_once("http://127.0.0.1:"))
            .and_then(|(_, p)| p.parse().ok())
            .unwrap_or_else(|| panic!("no loopback URL in {line:?}"));
        PreviewServer { child, port }
    }

    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.port)
    }

    /// One raw request (`target` exactly as sent, `host` as the Host
    /// header): the status and the body.
    pub fn get(&self, target: &str, host: &str) -> (u16, String) {
        let mut s = TcpStream::connect(("127.0.0.1", self.port)).expect("connects");
        write!(s, "GET {target} HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n").unwrap();
        let mut text = String::new();
        let _ = s.read_to_string(&mut text);
        let status = text.split(' ').nth(1).and_then(|c| c.parse().ok()).unwrap_or(0);
        let body = text.split_once("\r\n\r\n").map(|(_, b)| b.to_string()).unwrap_or_default();
        (status, body)
    }

    pub fn host(&self) -> String {
        format!("127.0.0.1:{}", self.port)
    }
}

impl Drop for PreviewServer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
