"""One WebSocket client connection whose framing is done by the `websockets` library
(17.4), for the conformance cases in conformance.py.

Why the sans-I/O `ClientProtocol` and not `websockets.sync.client.connect`: the sync
client's connection starts a thread that owns the socket from the opening handshake on,
so frames written past it and bytes read behind its back would race that thread. The
sans-I/O protocol is the same code the sync client runs (handshake request, the
Sec-WebSocket-Accept and subprotocol checks, the frame parser), with the socket ours:

- the opening handshake is `ClientProtocol.connect()` / `send_request()`, its response
  checked by the library (`handshake_exc`);
- frames to the server are `websockets.frames.Frame(...).serialize(mask=..., extensions=[])`
  written to the socket as they are: the cases need frames a client must not send
  (reserved bits, reserved opcodes, unmasked, oversized or fragmented control frames),
  so `Frame.check`, which refuses to serialize them, is skipped ([`RawFrame`]);
- frames from the server are read by the library's parser (`receive_data` then
  `events_received`), which also checks them: a server frame that breaks RFC 6455
  (masked, reserved bits, a bad close code, ...) is a failure of the case.

The protocol object answers nothing on our behalf: what it queues to send (a pong to a
server ping, the echo of a server close) is dropped, since each case decides what it
sends. Every read has a deadline; a wait that runs out raises `Timeout`.
"""

from __future__ import annotations

import socket
import time
from dataclasses import dataclass

from websockets.client import ClientProtocol
from websockets.frames import CLOSE, CONT, PING, PONG, TEXT, BINARY, Close, Frame
from websockets.http11 import Response
from websockets.uri import parse_uri

# Seconds any single wait for the server may take before the case fails.
READ_TIMEOUT = 2.0

OPCODE_NAMES = {0x0: "CONT", 0x1: "TEXT", 0x2: "BINARY", 0x8: "CLOSE", 0x9: "PING", 0xA: "PONG"}


class Timeout(Exception):
    """The server sent nothing (more) within the wait."""


class ServerError(Exception):
    """The server refused the opening handshake, or sent bytes the library's parser
    refuses (a frame that breaks RFC 6455)."""


class RawFrame(Frame):
    """A frame that `serialize` writes even when it breaks RFC 6455: the library still
    encodes the header, the length and the mask; only its refusal (`Frame.check`) of
    reserved bits, oversized and fragmented control frames is skipped. `opcode` may be a
    plain int for reserved opcodes."""

    def check(self) -> None:
        pass


@dataclass
class Event:
    """What the server sent: a whole data message (its fragments joined), a control
    frame, or the end of the TCP stream (`eof`)."""

    kind: str  # "text" | "binary" | "ping" | "pong" | "close" | "eof"
    data: bytes = b""
    code: int | None = None  # close: the code (None for an empty close body)
    reason: str = ""
    reset: bool = False  # eof: by a TCP reset rather than a FIN

    def __str__(self) -> str:
        if self.kind == "close":
            return "CLOSE (no body)" if self.code is None else f"CLOSE {self.code} {self.reason!r}"
        if self.kind == "eof":
            return "TCP reset" if self.reset else "TCP closed (FIN)"
        return f"{self.kind.upper()} {preview(self.data)}"


def preview(data: bytes, keep: int = 48) -> str:
    if len(data) <= keep:
        return f"{bytes(data)!r} ({len(data)} B)"
    return f"{bytes(data[:keep])!r}... ({len(data)} B)"


def describe(opcode: int, data: bytes, fin: bool, rsv: tuple[bool, bool, bool], mask: bool) -> str:
    name = OPCODE_NAMES.get(opcode, f"opcode 0x{opcode:X}")
    flags = [] if fin else ["FIN=0"]
    flags += [f"RSV{i + 1}" for i, bit in enumerate(rsv) if bit]
    if not mask:
        flags.append("UNMASKED")
    return f"{name} {preview(data)}" + (f" [{' '.join(flags)}]" if flags else "")


class Peer:
    """One client connection, opened (handshake done) on construction."""

    def __init__(self, url: str, subprotocols: list[str] | None = None, timeout: float = READ_TIMEOUT):
        uri = parse_uri(url)
        self.log: list[str] = []  # frames sent (>) and events received (<), for failure messages
        self.sock = socket.create_connection((uri.host, uri.port), timeout=timeout)
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.proto = ClientProtocol(uri, subprotocols=subprotocols, max_size=None)
        self.proto.send_request(self.proto.connect())
        for data in self.proto.data_to_send():
            self.sock.sendall(data)
        self.pending: list[Frame] = []
        self.partial: tuple[str, bytearray] | None = None
        self.eof: Event | None = None
        deadline = time.monotonic() + timeout
        response = None
        while response is None:
            self._fill(deadline, "the opening handshake's response")
            if self.eof is not None:
                raise ServerError(f"the server closed the connection during the opening handshake ({self.eof})")
            for ev in self.proto.events_received():
                if isinstance(ev, Response):
                    response = ev
                else:
                    self.pending.append(ev)
        if self.proto.handshake_exc is not None:
            raise ServerError(f"opening handshake refused: {self.proto.handshake_exc!r}")
        self.subprotocol = self.proto.subprotocol

    # --- sending

    def send(self, opcode: int, data: bytes = b"", *, fin: bool = True,
             rsv: tuple[bool, bool, bool] = (False, False, False), mask: bool = True) -> None:
        """Writes one frame, serialized by the library (masked unless `mask` is False)."""
        frame = RawFrame(opcode, data, fin, *rsv)
        self.send_bytes(frame.serialize(mask=mask, extensions=[]), describe(opcode, data, fin, rsv, mask))

    def send_bytes(self, raw: bytes, what: str, chop: int | None = None) -> None:
        """Writes `raw` as it is, in pieces of `chop` bytes with a pause between when
        asked. A write the server refuses (it closed) is logged, not raised: the case
        then reads what the server said."""
        self.log.append(f"> {what}" + (f" (written {chop} B at a time)" if chop else ""))
        self.sock.settimeout(READ_TIMEOUT)  # a read may have left a shorter one
        try:
            if chop is None:
                self.sock.sendall(raw)
            else:
                for i in range(0, len(raw), chop):
                    self.sock.sendall(raw[i:i + chop])
                    time.sleep(0.001)
        except OSError as e:
            self.log.append(f"  (write failed: {e!r})")

    def text(self, data: bytes | str, **kw) -> None:
        self.send(TEXT, data.encode() if isinstance(data, str) else data, **kw)

    def fragments(self, opcode: int, parts: list[bytes], between=None) -> None:
        """Sends one message as `parts`, the first with `opcode`, the rest as
        continuations; `between(i)` runs after fragment i (not after the last)."""
        for i, part in enumerate(parts):
            last = i == len(parts) - 1
            self.send(opcode if i == 0 else CONT, part, fin=last)
            if between is not None and not last:
                between(i)

    def ping(self, data: bytes = b"") -> None:
        self.send(PING, data)

    def close(self, code: int | None = None, reason: bytes = b"") -> None:
        body = b"" if code is None else code.to_bytes(2, "big") + reason
        self.send(CLOSE, body)

    # --- receiving

    def _fill(self, deadline: float, what: str) -> None:
        """Reads once from the socket into the library's parser."""
        left = deadline - time.monotonic()
        if left <= 0:
            raise Timeout(f"nothing from the server within {READ_TIMEOUT:g} s while waiting for {what}")
        self.sock.settimeout(left)
        try:
            data = self.sock.recv(1 << 16)
        except socket.timeout:
            raise Timeout(f"nothing from the server within {READ_TIMEOUT:g} s while waiting for {what}") from None
        except ConnectionResetError:
            self.eof = Event("eof", reset=True)
            self.proto.receive_eof()
            return
        if not data:
            self.eof = Event("eof")
            self.proto.receive_eof()
            return
        self.proto.receive_data(data)
        self.proto.data_to_send()  # what the library would answer: the cases decide that
        if self.proto.parser_exc is not None and not isinstance(self.proto.parser_exc, EOFError):
            raise ServerError(f"the server sent a frame the library refuses: {self.proto.parser_exc!r}")

    def next(self, timeout: float = READ_TIMEOUT, what: str = "a frame") -> Event:
        """The next message, control frame or end of stream from the server."""
        deadline = time.monotonic() + timeout
        while True:
            while self.pending:
                ev = self._take(self.pending.pop(0))
                if ev is not None:
                    self.log.append(f"< {ev}")
                    return ev
            if self.eof is not None:
                self.log.append(f"< {self.eof}")
                return self.eof
            self._fill(deadline, what)
            self.pending.extend(self.proto.events_received())

    def _take(self, f: Frame) -> Event | None:
        if f.opcode is PING:
            return Event("ping", bytes(f.data))
        if f.opcode is PONG:
            return Event("pong", bytes(f.data))
        if f.opcode is CLOSE:
            if len(f.data) == 0:
                return Event("close")
            c = Close.parse(f.data)
            return Event("close", code=c.code, reason=c.reason)
        if f.opcode is CONT:
            kind, buf = self.partial
            buf += f.data
        else:
            kind, buf = ("text" if f.opcode is TEXT else "binary"), bytearray(f.data)
        if not f.fin:
            self.partial = (kind, buf)
            return None
        self.partial = None
        return Event(kind, bytes(buf))

    def shut(self) -> None:
        try:
            self.sock.close()
        except OSError:
            pass


__all__ = ["BINARY", "CLOSE", "CONT", "PING", "PONG", "TEXT", "Event", "Peer", "READ_TIMEOUT",
           "RawFrame", "ServerError", "Timeout", "describe", "preview"]
