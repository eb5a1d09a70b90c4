//! The gRPC accept loop's connection hygiene, the counterpart of
//! [`conn`](super::conn) for HTTP/2 (tonic offers neither a cap nor a
//! timeout for a client that connects and says nothing):
//!
//! - **Connection cap** ([`ServeConfig::max_connections`], counted apart
//!   from HTTP's): past it the loop stops accepting, so further clients
//!   wait in the kernel's listen backlog until a connection closes.
//! - **Preface timeout** ([`ServeConfig::header_timeout`]): a connection
//!   that sends no byte at all within the header timeout is closed. (After
//!   its first bytes, HTTP/2 keep-alive pings, configured on the server in
//!   [`super::start`], close peers that stop answering.)
//!
//! [`ServeConfig::max_connections`]: super::ServeConfig::max_connections
//! [`ServeConfig::header_timeout`]: super::ServeConfig::header_timeout

use std::future::Future;
use std::io;
use std::pin::Pin;
use std::sync::Arc;
use std::task::{Context, Poll};
use std::time::Duration;
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{mpsc, OwnedSemaphorePermit, Semaphore};
use tokio_stream::wrappers::ReceiverStream;
use tonic::transport::server::{Connected, TcpConnectInfo};

/// The accepted connections, each holding one of `max` slots until it is
/// dropped, as the stream tonic's `serve_with_incoming` takes. The accept
/// loop ends when the server drops the stream.
pub(crate) fn capped_incoming(listener: TcpListener, max: usize, preface_timeout: Duration) -> ReceiverStream<io::Result<Capped>> {
    let (tx, rx) = mpsc::channel(1);
    let slots = Arc::new(Semaphore::new(max.clamp(1, Semaphore::MAX_PERMITS)));
    tokio::spawn(async move {
        loop {
            let Ok(permit) = slots.clone().acquire_owned().await else { break };
            let stream = tokio::select! {
                r = super::conn::accept_or_back_off(&listener) => match r {
                    Some(s) => s,
                    None => continue,
                },
                () = tx.closed() => break,
            };
            // Without TCP_NODELAY a reply's header, message and trailer frames wait on
            // Nagle's algorithm and the client's delayed ACK, about 40 ms per call on loopback.
            let _ = stream.set_nodelay(true);
            let capped = Capped { stream, _slot: permit, preface: Some(Box::pin(tokio::time::sleep(preface_timeout))) };
            if tx.send(Ok(capped)).await.is_err() {
                break;
            }
        }
    });
    ReceiverStream::new(rx)
}

/// A TCP connection that holds its slot of the cap until it is dropped,
/// and fails its reads if no byte arrives before the preface timeout.
#[derive(Debug)]
pub(crate) struct Capped {
    stream: TcpStream,
    _slot: OwnedSemaphorePermit,
    /// Running until the first byte is read.
    preface: Option<Pin<Box<tokio::time::Sleep>>>,
}

impl AsyncRead for Capped {
    fn poll_read(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &mut ReadBuf<'_>) -> Poll<io::Result<()>> {
        let this = self.get_mut();
        let before = buf.filled().len();
        match Pin::new(&mut this.stream).poll_read(cx, buf) {
            Poll::Ready(r) => {
                if buf.filled().len() > before {
                    this.preface = None;
                }
                Poll::Ready(r)
            }
            Poll::Pending => match this.preface.as_mut().map(|t| t.as_mut().poll(cx)) {
                Some(Poll::Ready(())) => Poll::Ready(Err(io::Error::new(io::ErrorKind::TimedOut, "no HTTP/2 preface within the header timeout"))),
                _ => Poll::Pending,
            },
        }
    }
}

impl AsyncWrite for Capped {
    fn poll_write(self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<io::Result<usize>> {
        Pin::new(&mut self.get_mut().stream).poll_write(cx, buf)
    }

    fn poll_flush(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().stream).poll_flush(cx)
    }

    fn poll_shutdown(self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.get_mut().stream).poll_shutdown(cx)
    }

    fn poll_write_vectored(self: Pin<&mut Self>, cx: &mut Context<'_>, bufs: &[io::IoSlice<'_>]) -> Poll<io::Result<usize>> {
        Pin::new(&mut self.get_mut().stream).poll_write_vectored(cx, bufs)
    }

    fn is_write_vectored(&self) -> bool {
        self.stream.is_write_vectored()
    }
}

impl Connected for Capped {
    type ConnectInfo = TcpConnectInfo;

    fn connect_info(&self) -> TcpConnectInfo {
        self.stream.connect_info()
    }
}
