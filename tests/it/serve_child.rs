//! `rulemesh serve` as a child process on free loopback ports: for tests
//! that need the real binary's flags, its log on stderr, a graceful
//! SIGTERM, or a process of its own (the memory guard reads the resident
//! memory of the whole process, so a server sharing the test process with
//! a print test's gigabyte would measure that test, not itself).

#![allow(dead_code)]

use crate::common;
use crate::scaleout::free_port;
use std::net::{SocketAddr, TcpStream};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A running `rulemesh serve`; killed when dropped (a failing test leaves no server behind).
pub struct ServeChild {
    /// The process; its stderr is piped when the child was started with [`ServeChild::piped`].
    pub child: Child,
    /// The HTTP address it accepts on.
    pub http: SocketAddr,
    /// The gRPC address it accepts on.
    pub grpc: SocketAddr,
}

impl ServeChild {
    /// `rulemesh serve` with `args` after the address flags and `env` added,
    /// stderr passed through; returns once the HTTP port accepts.
    pub fn start(args: &[&str], env: &[(&str, String)]) -> Self {
        Self::spawn(args, env, Stdio::inherit())
    }

    /// As [`ServeChild::start`] with stderr piped, for [`common::stderr_lines`].
    pub fn piped(args: &[&str], env: &[(&str, String)]) -> Self {
        Self::spawn(args, env, Stdio::piped())
    }

    fn spawn(args: &[&str], env: &[(&str, String)], stderr: Stdio) -> Self {
        let http = SocketAddr::from(([127, 0, 0, 1], free_port()));
        let grpc = SocketAddr::from(([127, 0, 0, 1], free_port()));
        let child = Command::new(common::bin())
            .args(["serve", "--http", &http.to_string(), "--grpc", &grpc.to_string()])
            .args(args)
            .envs(env.iter().map(|(k, v)| (*k, v.as_str())))
            .stdout(Stdio::null())
            .stderr(stderr)
            .spawn()
            .expect("spawn rulemesh serve");
        let mut served = Self { child, http, grpc };
        let deadline = Instant::now() + Duration::from_secs(20);
        while TcpStream::connect(http).is_err() {
            if let Ok(Some(status)) = served.child.try_wait() {
                panic!("rulemesh serve exited before accepting: {status}");
            }
            assert!(Instant::now() < deadline, "rulemesh serve did not accept on {http} within 20 s");
            std::thread::sleep(Duration::from_millis(20));
        }
        served
    }

    /// The HTTP base URL, `http://127.0.0.1:PORT`.
    pub fn base(&self) -> String {
        format!("http://{}", self.http)
    }

    /// The lines the child writes to stderr (started with [`ServeChild::piped`]).
    pub fn stderr_lines(&mut self) -> std::sync::mpsc::Receiver<String> {
        common::stderr_lines(&mut self.child)
    }

    /// Stops the child with SIGTERM (a graceful shutdown, which flushes
    /// exported spans) and waits up to 20 s before killing it.
    pub fn terminate(mut self) {
        let _ = Command::new("kill").args(["-TERM", &self.child.id().to_string()]).status();
        let deadline = Instant::now() + Duration::from_secs(20);
        while self.child.try_wait().ok().flatten().is_none() && Instant::now() < deadline {
            std::thread::sleep(Duration::from_millis(20));
        }
        // Drop kills it if it is still running.
    }
}

impl Drop for ServeChild {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}
