# syntax=docker/dockerfile:1
# rulemesh serve as a container: build with cargo (dependencies compiled in a
# layer of their own, so editing src/ does not rebuild them), then copy the one
# binary into a slim Debian runtime that runs as a non-root user. The grammar
# library is embedded in the binary; nothing else is needed at run time.
#   docker build -t rulemesh .
#   docker run -p 8080:8080 -p 50051:50051 rulemesh
# See docs/deploy.md.

FROM rust:1-slim-bookworm AS build
# manifold-rs (the boolean union of print=true) builds Manifold's C++ with CMake and Ninja.
RUN apt-get update \
    && apt-get install -y --no-install-recommends cmake=3.25.1-1 ninja-build=1.11.1-2~deb12u1 g++=4:12.2.0-3 \
    && rm -rf /var/lib/apt/lists/*
WORKDIR /src
# Dependencies first: stub crates with the real manifests build every
# dependency into this layer, reused until a Cargo.toml or Cargo.lock change.
# The workspace's members (crates/, ARCHITECTURE.md "Code map") are copied
# manifest by manifest: their sources would void this layer's cache.
COPY Cargo.toml Cargo.lock ./
COPY crates/core/Cargo.toml crates/core/build.rs crates/core/
COPY crates/lang/Cargo.toml crates/lang/
COPY crates/engine/Cargo.toml crates/engine/
COPY crates/service/Cargo.toml crates/service/build.rs crates/service/
COPY proto ./proto
COPY grammars ./grammars
# manifold-rs with the determinism fix to Manifold (vendor/manifold-rs/PATCHES.md).
COPY vendor ./vendor
RUN mkdir -p src bench tests/it crates/core/src crates/lang/src crates/engine/src crates/service/src \
    && echo 'fn main() {}' > src/main.rs \
    && touch src/lib.rs bench/decode_strips.rs tests/it/main.rs crates/core/src/lib.rs crates/lang/src/lib.rs crates/engine/src/lib.rs crates/service/src/lib.rs \
    && cargo build --release --locked --bin rulemesh \
    && rm -rf src crates/core/src crates/lang/src crates/engine/src crates/service/src
# Then the crates themselves; every stub is touched, or cargo, seeing stubs
# newer than the copied sources, would keep the stubs' empty crates.
COPY src ./src
COPY crates ./crates
RUN touch src/main.rs src/lib.rs crates/core/src/lib.rs crates/lang/src/lib.rs crates/engine/src/lib.rs crates/service/src/lib.rs \
    && cargo build --release --locked --bin rulemesh \
    && cp target/release/rulemesh /usr/local/bin/rulemesh

FROM debian:bookworm-slim AS runtime
# tini as PID 1: it forwards SIGTERM to rulemesh (which drains on it) and reaps
# orphans, e.g. a HEALTHCHECK's head/grep left behind when its bash is killed
# on timeout; rulemesh itself never waits on children it did not spawn.
RUN apt-get update \
    && apt-get install -y --no-install-recommends tini=0.19.0-1+b3 \
    && rm -rf /var/lib/apt/lists/* \
    && groupadd --system --gid 10001 rulemesh \
    && useradd --system --uid 10001 --gid 10001 --no-create-home --shell /usr/sbin/nologin rulemesh
COPY --from=build /usr/local/bin/rulemesh /usr/local/bin/rulemesh
# Listen on every interface inside the container (the binary's defaults are loopback).
ENV RULEMESH_HTTP=0.0.0.0:8080 \
    RULEMESH_GRPC=0.0.0.0:50051 \
    RULEMESH_LOG=info
EXPOSE 8080 50051
# The group too, as deploy/k8s/deployment.yaml (runAsGroup) has it; useradd --system alone picks gid 999.
USER 10001:10001
# /healthz over bash's /dev/tcp: the slim image has no curl. The port (and
# address, unless it is a wildcard) comes from RULEMESH_HTTP, so moving the
# listener with that variable (host networking) moves the check with it.
HEALTHCHECK --interval=10s --timeout=3s --start-period=5s --retries=3 \
    CMD ["bash", "-c", "a=${RULEMESH_HTTP:-0.0.0.0:8080}; h=${a%:*}; h=${h#[}; h=${h%]}; case $h in 0.0.0.0|::) h=127.0.0.1;; esac; exec 3<>/dev/tcp/$h/${a##*:} && printf 'GET /healthz HTTP/1.0\\r\\n\\r\\n' >&3 && head -n 1 <&3 | grep -q ' 200 '"]
STOPSIGNAL SIGTERM
ENTRYPOINT ["/usr/bin/tini", "--", "/usr/local/bin/rulemesh"]
CMD ["serve"]
