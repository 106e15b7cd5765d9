"""RFC 6455 conformance of the hub's server side, modelled on the Autobahn TestSuite's
sections (numbers in each case's label: 1 framing, 2 pings/pongs, 3 reserved bits,
4 opcodes, 5 fragmentation, 6 UTF-8, 7 close handling, 9 limits), with the `websockets`
library as the frame encoder and decoder (peer.py) and the test logic here.

Two paths through the hub's one WebSocket layer:
- rosbridge v2 (labels without a prefix): a message "arrives whole" when the client's
  own `publish` on a topic it subscribed to comes back to it with the same data;
- fleetlink.v1 (labels `A/...`): the agent handshake (HELLO -> WELCOME, docs/protocol.md
  section 1), WebSocket-level pings, a text message (answered by a STATUS frame), and
  frames that break the protocol.

Each case prints one line (PASS/FAIL, its label and what it checks); a failure says
what RFC 6455 requires, what the server did, and the frames sent (>) and received (<).
Every read is bounded (peer.READ_TIMEOUT). Exit status: 0 when every case passed.
"""

from __future__ import annotations

import argparse
import json
import struct
import sys
import time
import traceback

import cbor2

from peer import (BINARY, CLOSE, CONT, PING, PONG, TEXT, Event, Peer, RawFrame, READ_TIMEOUT,
                  ServerError, Timeout, preview)

SUBPROTOCOL = "fleetlink.v1"
# A text payload with 2-, 3- and 4-byte UTF-8 sequences, up to the last code point.
MULTIBYTE = "κόσμε €𝄞 \U0010FFFF"
# Autobahn 6.3.1's payload: "κόσμε", a UTF-16 surrogate (ED A0 80), "edited".
BAD_UTF8 = b"\xce\xba\xe1\xbd\xb9\xcf\x83\xce\xbc\xce\xb5\xed\xa0\x80edited"
PONG_RULE = "RFC 6455 5.5.2: a ping MUST be answered by a pong with the same payload"


class Fail(Exception):
    """A case's failure: what RFC 6455 requires and what the server did."""


CASES: list[tuple[str, str, object]] = []


def case(label: str, title: str):
    def register(fn):
        CASES.append((label, title, fn))
        return fn
    return register


class Ctx:
    """What the cases connect to, and the connections the running case opened."""

    def __init__(self, args):
        self.rosbridge_url = args.rosbridge_url
        self.agent_url = args.agent_url
        self.robot = args.robot
        self.robot_token = args.robot_token
        self.max_size = args.max_message_size
        self.peers: list[Peer] = []
        self.topics = 0

    def open(self, url: str | None = None, subprotocols=None) -> Peer:
        p = Peer(url or self.rosbridge_url, subprotocols)
        self.peers.append(p)
        return p

    def topic(self) -> str:
        self.topics += 1
        return f"/ws_conformance/t{self.topics}"

    def shut_all(self) -> None:
        for p in self.peers:
            p.shut()
        self.peers = []


# --- rosbridge helpers

def rosbridge(ctx: Ctx) -> tuple[Peer, str]:
    """A rosbridge connection that advertises and subscribes to a topic of its own."""
    p, t = ctx.open(), ctx.topic()
    p.text(json.dumps({"op": "advertise", "topic": t, "type": "std_msgs/String"}))
    p.text(json.dumps({"op": "subscribe", "topic": t, "type": "std_msgs/String"}))
    return p, t


def publish(topic: str, data: str) -> bytes:
    return json.dumps({"op": "publish", "topic": topic, "msg": {"data": data}},
                      ensure_ascii=False).encode()


def publish_raw(topic: str, data: bytes) -> bytes:
    """A publish whose data string is these bytes as they are (UTF-8 or not)."""
    return b'{"op":"publish","topic":"' + topic.encode() + b'","msg":{"data":"' + data + b'"}}'


def publish_of_size(topic: str, size: int) -> tuple[bytes, str]:
    """A publish exactly `size` bytes long, and its data."""
    fill = size - len(publish(topic, ""))
    assert fill >= 0, f"{size} bytes cannot hold a publish on {topic}"
    data = "x" * fill
    return publish(topic, data), data


def op_of(ev: Event) -> dict | None:
    """A rosbridge operation the server sent (JSON text or CBOR binary)."""
    if ev.kind == "text":
        try:
            text = ev.data.decode("utf-8")
        except UnicodeDecodeError as e:
            raise Fail(f"RFC 6455 8.1: a text message MUST be UTF-8; the server sent one that is not ({e})")
        return json.loads(text)
    if ev.kind == "binary":
        return cbor2.loads(ev.data)
    return None


def expect_echo(p: Peer, topic: str, data: str, pings: list[bytes] = (), what: str = "") -> None:
    """Reads until the client's own publish on `topic` comes back, and a pong for each of
    `pings`; the data must be what was sent and the pongs must carry the pings'
    payloads, in order (RFC 6455 5.5.2, 5.5.3)."""
    pongs: list[bytes] = []
    got = None
    while got is None or len(pongs) < len(pings):
        try:
            ev = p.next(what=f"the published message back{what}" if got is None else "the pongs")
        except Timeout as e:
            raise Fail(f"the message{what} is valid RFC 6455 and must be delivered whole"
                       + (f" and each ping answered by its pong ({PONG_RULE})" if pings else "")
                       + f"; {e} (pongs so far: {pongs})") from None
        if ev.kind == "pong":
            pongs.append(ev.data)
            continue
        if ev.kind in ("close", "eof"):
            raise Fail(f"the message{what} is valid RFC 6455 and must be delivered; "
                       f"the server ended the connection instead: {ev}")
        op = op_of(ev)
        if op is None:
            continue
        if op.get("op") == "status" and op.get("level") == "error":
            raise Fail(f"the message{what} must arrive whole; the server answered: {op.get('msg')}")
        if op.get("op") == "publish" and op.get("topic") == topic:
            got = op.get("msg", {}).get("data")
            if got != data:
                raise Fail(f"the message{what} must arrive whole (fragments joined in order); data came "
                           f"back as {preview(str(got).encode())} instead of {preview(data.encode())}")
    if pongs != list(pings):
        raise Fail("RFC 6455 5.5.2/5.5.3: each ping is answered by a pong with the same payload "
                   f"(in order); sent pings {list(pings)}, got pongs {pongs}")


# Why a close frame is due when the server fails a connection (RFC 6455 7.1.7).
FAIL_NEEDS_CLOSE = ("RFC 6455 7.1.7: an endpoint failing an established connection SHOULD send a "
                    "close frame with the status code before closing it")


def expect_close(p: Peer, codes: set[int | None], rfc: str, forbid_topic: str | None = None,
                 forbid_pong: bool = False, without_close: str = FAIL_NEEDS_CLOSE) -> Event:
    """Reads until the server's close frame: its code must be one of `codes`, and the
    server must then close the TCP connection. Messages before it are allowed, except an
    echo on `forbid_topic` (the offending frame was processed) or a pong when
    `forbid_pong`. `without_close` says what a TCP close without a close frame breaks."""
    while True:
        try:
            ev = p.next(what="the server's close frame")
        except Timeout:
            raise Fail(f"{rfc}; the server sent no close frame within {READ_TIMEOUT:g} s "
                       "(the connection stayed open)") from None
        if ev.kind == "eof":
            raise Fail(f"{rfc}; the server closed the TCP connection without a close frame"
                       f" ({ev})" + (f". {without_close}" if without_close else ""))
        if ev.kind == "close":
            break
        if ev.kind == "pong" and forbid_pong:
            raise Fail(f"{rfc}; the server answered a frame after the one it had to fail on: {ev}")
        if forbid_topic is not None:
            op = op_of(ev)
            if op and op.get("op") == "publish" and op.get("topic") == forbid_topic:
                raise Fail(f"{rfc}; the server processed the offending message instead: {ev}")
    if ev.code not in codes:
        want = ", ".join("no code" if c is None else str(c) for c in sorted(codes, key=lambda c: c or 0))
        raise Fail(f"{rfc}; the server's close frame carried {ev} instead of {want}")
    expect_tcp_close(p)
    return ev


def expect_tcp_close(p: Peer) -> None:
    try:
        ev = p.next(what="the end of the TCP connection")
    except Timeout:
        raise Fail("RFC 6455 7.1.1: once the close handshake is done the server SHOULD close the "
                   f"TCP connection first; it was still open {READ_TIMEOUT:g} s later") from None
    if ev.kind != "eof":
        raise Fail(f"RFC 6455 5.5.1: after its close frame the server MUST NOT send more data; it sent {ev}")


def expect_pong(p: Peer, payload: bytes, what: str = "the pong") -> None:
    """The next frame that is not a data message is the pong to `payload`."""
    while True:
        try:
            ev = p.next(what=what)
        except Timeout as e:
            raise Fail(f"{PONG_RULE} ({preview(payload)}); {e}") from None
        if ev.kind == "pong" and ev.data == payload:
            return
        if ev.kind not in ("text", "binary"):
            raise Fail(f"{PONG_RULE} ({preview(payload)}); the server sent {ev}")


def expect_alive(p: Peer, tag: bytes = b"still there?") -> None:
    """The connection still serves: a ping is answered by its pong, nothing closes."""
    p.ping(tag)
    expect_pong(p, tag, "the pong that shows the connection is still open")


# RFC 6455 5.1 makes the close frame optional here; 1002 is expected as on every other failure.
UNMASKED_CLOSE = ("RFC 6455 5.1 only says the server MAY send close 1002 here (closing the connection "
                  "is the MUST, and that was done); this suite expects the 1002 the server sends on "
                  "every other protocol error")


def protocol_error(p: Peer, rfc: str, **kw) -> None:
    expect_close(p, {1002}, f"{rfc} -> the server MUST fail the connection (expected: close 1002)", **kw)


def invalid_utf8(p: Peer, **kw) -> None:
    expect_close(p, {1007}, "RFC 6455 8.1: a text message that is not UTF-8 MUST fail the "
                 "connection (expected: close 1007)", **kw)


def split_inside_code_points(raw: bytes) -> list[bytes]:
    """Cuts `raw` before every UTF-8 continuation byte that follows a lead byte: each
    multi-byte character is split between fragments."""
    cuts = [i for i in range(1, len(raw)) if 0x80 <= raw[i] <= 0xBF and raw[i - 1] >= 0xC0]
    parts, start = [], 0
    for c in cuts:
        parts.append(raw[start:c])
        start = c
    parts.append(raw[start:])
    return parts


# === 1 Framing

def echo_sized(ctx: Ctx, size: int) -> None:
    p, t = rosbridge(ctx)
    msg, data = publish_of_size(t, size)
    p.text(msg)
    expect_echo(p, t, data)


@case("1.1.2-7", "text messages of 125, 126, 65535 and 65536 bytes (every length format) arrive whole")
def _(ctx):
    for size in (125, 126, 65535, 65536):
        echo_sized(ctx, size)


@case("1.2.7", "binary (CBOR) message of 70000 bytes arrives whole")
def _(ctx):
    p, t = rosbridge(ctx)
    data = "b" * 70000
    p.send(BINARY, cbor2.dumps({"op": "publish", "topic": t, "msg": {"data": data}}))
    expect_echo(p, t, data)


@case("1.x.1", "an unmasked client frame -> close 1002 (RFC 6455 5.1)")
def _(ctx):
    p, t = rosbridge(ctx)
    p.text(publish(t, "unmasked"), mask=False)
    protocol_error(p, "RFC 6455 5.1: a server MUST close the connection on a frame that is not masked",
                   forbid_topic=t, without_close=UNMASKED_CLOSE)


@case("1.x.2", "a 64-bit length with its top bit set -> connection failed (1002 or 1009)")
def _(ctx):
    p = ctx.open()
    # The library cannot write such a length: the header is written by hand.
    header = bytes([0x82, 0x80 | 127]) + ((1 << 63) | 5).to_bytes(8, "big") + b"\x00\x00\x00\x00"
    p.send_bytes(header + b"hello", "BINARY, 64-bit length 2^63+5 [top bit set], 5 bytes follow")
    expect_close(p, {1002, 1009}, "RFC 6455 5.2: the most significant bit of a 64-bit length MUST "
                 "be 0 -> the server fails the connection")


# === 2 Pings and pongs

def ping_pong(ctx: Ctx, payload: bytes, chop: int | None = None) -> None:
    p = ctx.open()
    if chop is None:
        p.ping(payload)
    else:
        p.send_bytes(RawFrame(PING, payload).serialize(mask=True, extensions=[]),
                     f"PING {preview(payload)}", chop=chop)
    expect_pong(p, payload)


@case("2.1-2.4", "pings with empty, binary and 125-byte payloads -> pongs with the same payloads")
def _(ctx):
    for payload in (b"", bytes([0x00, 0xFF, 0xFE, 0x80, 0x00, 0xFF]), bytes(range(125))):
        ping_pong(ctx, payload)


@case("2.5", "ping with 126 bytes of payload -> close 1002, no pong")
def _(ctx):
    p = ctx.open()
    p.send(PING, b"\xfe" * 126)
    protocol_error(p, "RFC 6455 5.5: control frames MUST have a payload of 125 bytes or less",
                   forbid_pong=True)


@case("2.6", "ping with 125 bytes written one byte at a time -> pong with the same payload")
def _(ctx): ping_pong(ctx, b"*" * 125, chop=1)


@case("2.7/2.8", "unsolicited pongs (empty, and with payload) are not answered")
def _(ctx):
    p = ctx.open()
    p.send(PONG, b"")
    p.send(PONG, b"unsolicited pong payload")
    p.ping(b"after the pongs")
    # A pong answering either unsolicited pong would come before this one.
    expect_pong(p, b"after the pongs", "the pong to the ping after the unsolicited pongs")


@case("2.10", "ten pings in a row -> ten pongs with their payloads, in order")
def _(ctx):
    p = ctx.open()
    payloads = [f"payload-{i}".encode() for i in range(10)]
    for d in payloads:
        p.ping(d)
    got = [p.next(what=f"pong {i + 1} of 10") for i in range(10)]
    if [(e.kind, e.data) for e in got] != [("pong", d) for d in payloads]:
        raise Fail("RFC 6455 5.5.2: every ping MUST be answered by a pong with its payload; "
                   f"got {[str(e) for e in got]}")


# === 3 Reserved bits

@case("3.1", "RSV1 set on a text frame (no extension negotiated) -> close 1002")
def _(ctx):
    p, t = rosbridge(ctx)
    p.text(publish(t, "rsv1"), rsv=(True, False, False))
    protocol_error(p, "RFC 6455 5.2: a non-zero RSV bit without a negotiated extension", forbid_topic=t)


@case("3.2", "a valid message, then RSV2 on a text frame -> echo, then close 1002")
def _(ctx):
    p, t = rosbridge(ctx)
    p.text(publish(t, "first"))
    expect_echo(p, t, "first")
    p.text(publish(t, "rsv2"), rsv=(False, True, False))
    protocol_error(p, "RFC 6455 5.2: a non-zero RSV bit without a negotiated extension", forbid_topic=t)


@case("3.6", "RSV2+RSV3 set on a ping -> close 1002, no pong")
def _(ctx):
    p = ctx.open()
    p.send(PING, b"rsv", rsv=(False, True, True))
    protocol_error(p, "RFC 6455 5.2: a non-zero RSV bit without a negotiated extension", forbid_pong=True)


@case("3.7", "RSV1+2+3 set on a close frame -> close 1002")
def _(ctx):
    p = ctx.open()
    p.send(CLOSE, (1000).to_bytes(2, "big"), rsv=(True, True, True))
    protocol_error(p, "RFC 6455 5.2: a non-zero RSV bit without a negotiated extension")


# === 4 Opcodes

def reserved_opcodes(ctx: Ctx, opcodes) -> None:
    wrong = []
    for op in opcodes:
        p = ctx.open()
        p.send(op, b"reserved opcode")
        p.ping(b"after the reserved opcode")
        try:
            protocol_error(p, f"RFC 6455 5.2: opcode 0x{op:X} is reserved", forbid_pong=True)
        except (Fail, Timeout, ServerError) as e:
            wrong.append(f"0x{op:X}: {e}")
    if wrong:
        raise Fail("; ".join(wrong))


@case("4.1.1-5", "reserved data opcodes 0x3-0x7 -> close 1002 (each on its own connection)")
def _(ctx): reserved_opcodes(ctx, range(0x3, 0x8))


@case("4.2.1-5", "reserved control opcodes 0xB-0xF -> close 1002 (each on its own connection)")
def _(ctx): reserved_opcodes(ctx, range(0xB, 0x10))


# === 5 Fragmentation

@case("5.1-5.2", "a fragmented ping, and a fragmented pong (FIN=0) -> close 1002 each")
def _(ctx):
    for opcode in (PING, PONG):
        p = ctx.open()
        p.send(opcode, b"frag", fin=False)
        p.send(CONT, b"ment", fin=True)
        protocol_error(p, "RFC 6455 5.5: control frames MUST NOT be fragmented", forbid_pong=True)


@case("5.3", "a text message in 2 fragments arrives whole")
def _(ctx):
    p, t = rosbridge(ctx)
    msg = publish(t, "two fragments")
    p.fragments(TEXT, [msg[:20], msg[20:]])
    expect_echo(p, t, "two fragments")


@case("5.6", "a text message in 2 fragments with a ping between -> pong, message whole")
def _(ctx):
    p, t = rosbridge(ctx)
    msg = publish(t, "ping in between")
    p.fragments(TEXT, [msg[:25], msg[25:]], between=lambda i: p.ping(b"between"))
    expect_echo(p, t, "ping in between", pings=[b"between"])


@case("5.9", "a continuation frame with no message started -> close 1002")
def _(ctx):
    p, t = rosbridge(ctx)
    p.send(CONT, publish(t, "nothing to continue"), fin=True)
    p.text(publish(t, "after"))
    protocol_error(p, "RFC 6455 5.4: a continuation frame continues a fragmented message; "
                   "there was none", forbid_topic=t)


@case("5.12", "a continuation frame (FIN=0) with no message started -> close 1002")
def _(ctx):
    p, t = rosbridge(ctx)
    p.send(CONT, b"fragment", fin=False)
    p.text(publish(t, "after"))
    protocol_error(p, "RFC 6455 5.4: a continuation frame continues a fragmented message; "
                   "there was none", forbid_topic=t)


@case("5.18", "a new text, or binary, frame while a fragmented message is open -> close 1002 each")
def _(ctx):
    for opcode in (TEXT, BINARY):
        p, t = rosbridge(ctx)
        msg = publish(t, "interrupted")
        p.send(TEXT, msg[:10], fin=False)
        p.send(opcode, msg if opcode == TEXT else cbor2.dumps(json.loads(msg)), fin=True)
        protocol_error(p, "RFC 6455 5.4: the fragments of one message MUST NOT be interleaved with "
                       "another message's frames", forbid_topic=t)


@case("5.19", "a text message in 8 fragments with a ping between each -> 7 pongs in order, message whole")
def _(ctx):
    p, t = rosbridge(ctx)
    data = "many fragments, pings between them"
    msg = publish(t, data)
    parts = [msg[len(msg) * i // 8:len(msg) * (i + 1) // 8] for i in range(8)]
    pings = [f"ping {i}".encode() for i in range(len(parts) - 1)]
    p.fragments(TEXT, parts, between=lambda i: p.ping(pings[i]))
    expect_echo(p, t, data, pings=pings)


@case("5.20", "a text message sent one byte per fragment (multi-byte characters included) arrives whole")
def _(ctx):
    p, t = rosbridge(ctx)
    msg = publish(t, MULTIBYTE)
    p.fragments(TEXT, [msg[i:i + 1] for i in range(len(msg))])
    expect_echo(p, t, MULTIBYTE)


# === 6 UTF-8

@case("6.1.1", "an empty text message is valid: the connection stays open")
def _(ctx):
    p = ctx.open()
    p.text(b"")
    expect_alive(p)


@case("6.1.3", "empty fragments (first, middle and last) around the text: message whole")
def _(ctx):
    p, t = rosbridge(ctx)
    msg = publish(t, "empty fragments")
    p.fragments(TEXT, [b"", msg[:30], b"", msg[30:], b""])
    expect_echo(p, t, "empty fragments")


@case("6.2.3", "valid multi-byte characters split inside their code points across fragments are accepted")
def _(ctx):
    p, t = rosbridge(ctx)
    parts = split_inside_code_points(publish(t, MULTIBYTE))
    assert len(parts) > 5
    p.fragments(TEXT, parts)
    expect_echo(p, t, MULTIBYTE, what=" (split inside its characters)")


@case("6.3.1-2", "invalid UTF-8 (a surrogate) in a text message, whole and one byte per fragment -> close 1007")
def _(ctx):
    p = ctx.open()
    p.text(BAD_UTF8)
    invalid_utf8(p)
    p = ctx.open()
    p.fragments(TEXT, [BAD_UTF8[i:i + 1] for i in range(len(BAD_UTF8))])
    invalid_utf8(p)


@case("6.4.x", "a text message whose last fragment holds an invalid byte -> close 1007")
def _(ctx):
    p, t = rosbridge(ctx)
    msg = publish_raw(t, b"valid so far \xff")
    p.fragments(TEXT, [msg[:20], msg[20:-5], msg[-5:]])
    invalid_utf8(p, forbid_topic=t)


@case("6.x", "invalid UTF-8 in the data of a connection's first publish -> close 1007")
def _(ctx):
    p, t = rosbridge(ctx)
    p.text(publish_raw(t, b"bad \xed\xa0\x80 bytes"))
    invalid_utf8(p, forbid_topic=t)


@case("6.6-6.21", "invalid sequences in a publish after a valid one of the same shape -> close 1007 each")
def _(ctx):
    sequences = {
        "overlong '/' (C0 AF)": b"\xc0\xaf",
        "overlong 3-byte (E0 80 AF)": b"\xe0\x80\xaf",
        "surrogate U+DFFF (ED BF BF)": b"\xed\xbf\xbf",
        "above U+10FFFF (F4 90 80 80)": b"\xf4\x90\x80\x80",
        "lone continuation byte (80)": b"\x80",
        "truncated 3-byte sequence (E2 82)": b"\xe2\x82",
        "5-byte sequence (F8 88 80 80 80)": b"\xf8\x88\x80\x80\x80",
        "byte FE": b"\xfe",
    }
    wrong = []
    for name, seq in sequences.items():
        p, t = rosbridge(ctx)
        p.text(publish(t, "valid"))
        try:
            expect_echo(p, t, "valid")
            p.text(publish_raw(t, b"abc" + seq + b"def"))
            invalid_utf8(p, forbid_topic=t)
        except (Fail, Timeout, ServerError) as e:
            wrong.append(f"{name}: {e}")
    if wrong:
        raise Fail("; ".join(wrong))


# === 7 Close handling

def answered_close(p: Peer, sent: int | None, what: str, **kw) -> None:
    """The server answers a valid close with a close, then closes the TCP connection. The
    answer's body is optional (RFC 6455 5.5.1: the answer "typically echos" the code):
    the code sent back, 1000, or no body pass, as in Autobahn ("... or empty")."""
    expect_close(p, {None, 1000, sent}, f"RFC 6455 5.5.1: a close frame ({what}) MUST be answered "
                 "by a close frame", without_close="", **kw)


@case("7.1.1", "a message, then close 1000 with a reason -> message back, close answered, TCP closed")
def _(ctx):
    p, t = rosbridge(ctx)
    p.text(publish(t, "before the close"))
    expect_echo(p, t, "before the close")
    p.close(1000, b"bye")
    answered_close(p, 1000, "1000 'bye'")


@case("7.1.3-4", "close, then a ping and a text message -> close answered, neither of them")
def _(ctx):
    p, t = rosbridge(ctx)
    p.close(1000)
    p.ping(b"after close")
    p.text(publish(t, "after close"))
    answered_close(p, 1000, "1000, then a ping and a publish (to be discarded, RFC 6455 1.4)",
                   forbid_topic=t, forbid_pong=True)


@case("7.1.5", "a fragmented message open, close, then its last fragment -> close answered, not delivered")
def _(ctx):
    p, t = rosbridge(ctx)
    msg = publish(t, "cut by a close")
    p.send(TEXT, msg[:15], fin=False)
    p.close(1000)
    p.send(CONT, msg[15:], fin=True)
    answered_close(p, 1000, "1000 between the fragments of a message; what follows is discarded, "
                   "RFC 6455 1.4", forbid_topic=t)


@case("7.3.1", "close with an empty body -> close answered, TCP closed")
def _(ctx):
    p = ctx.open()
    p.close()
    answered_close(p, None, "with no body")


@case("7.3.2", "close with a 1-byte body -> close 1002")
def _(ctx):
    p = ctx.open()
    p.send(CLOSE, b"\x03")
    protocol_error(p, "RFC 6455 5.5.1: a close body starts with a 2-byte status code")


@case("7.3.5", "close 1000 with a 123-byte reason (125-byte payload) -> close answered")
def _(ctx):
    p = ctx.open()
    p.close(1000, b"r" * 123)
    answered_close(p, 1000, "1000 with a 123-byte reason")


@case("7.3.6", "close with a 126-byte payload -> close 1002")
def _(ctx):
    p = ctx.open()
    p.close(1000, b"r" * 124)
    protocol_error(p, "RFC 6455 5.5: control frames MUST have a payload of 125 bytes or less")


@case("7.5.1", "close 1000 with a reason that is not UTF-8 -> close 1007")
def _(ctx):
    p = ctx.open()
    p.close(1000, BAD_UTF8)
    expect_close(p, {1007}, "RFC 6455 5.5.1/8.1: a close reason is UTF-8; one that is not fails "
                 "the connection (close 1007)")


def close_codes(ctx: Ctx, codes, valid: bool) -> None:
    wrong = []
    for code in codes:
        p = ctx.open()
        p.close(code, b"code test")
        try:
            if valid:
                answered_close(p, code, f"with the valid code {code}")
            else:
                protocol_error(p, f"RFC 6455 7.4: {code} is not a code an endpoint may send")
        except (Fail, Timeout, ServerError) as e:
            wrong.append(f"{code}: {e}")
    if wrong:
        raise Fail("; ".join(wrong))


@case("7.7.1-13", "valid close codes (1000-1003, 1007-1011, 3000, 3999, 4000, 4999) -> close answered")
def _(ctx): close_codes(ctx, [1000, 1001, 1002, 1003, 1007, 1008, 1009, 1010, 1011, 3000, 3999, 4000, 4999], True)


@case("7.7.x", "IANA-registered close codes 1012-1014 (RFC 6455 11.7 registry) -> close answered")
def _(ctx): close_codes(ctx, [1012, 1013, 1014], True)


@case("7.9.1-9", "close codes no endpoint may send (0, 999, 1004-1006, 1015, 1016, 1100, 2000, 2999) -> 1002")
def _(ctx): close_codes(ctx, [0, 999, 1004, 1005, 1006, 1015, 1016, 1100, 2000, 2999], False)


# === 9 Limits (the hub runs with --max-message-size)

def too_big(p: Peer) -> None:
    expect_close(p, {1009}, "RFC 6455 7.4.1: a message too big to process fails the connection with 1009")


@case("9.x.1", "a message of exactly --max-message-size bytes arrives whole")
def _(ctx): echo_sized(ctx, ctx.max_size)


@case("9.x.2", "a message one byte over --max-message-size -> close 1009")
def _(ctx):
    p, t = rosbridge(ctx)
    msg, _ = publish_of_size(t, ctx.max_size + 1)
    p.text(msg)
    too_big(p)


@case("9.x.3", "fragments each under the limit that add up to one byte over it -> close 1009")
def _(ctx):
    p, t = rosbridge(ctx)
    msg, _ = publish_of_size(t, ctx.max_size + 1)
    half = len(msg) // 2
    p.fragments(TEXT, [msg[:half], msg[half:]])
    too_big(p)


@case("9.x.4", "a frame header announcing 4 GiB -> close 1009 without waiting for the payload")
def _(ctx):
    p = ctx.open()
    header = bytes([0x82, 0x80 | 127]) + (4 << 30).to_bytes(8, "big") + b"\x01\x02\x03\x04"
    p.send_bytes(header + b"\x00" * 16, "BINARY header, 64-bit length 4 GiB, then 16 bytes of it")
    too_big(p)


@case("10.1.1", "a message near the limit in 1300-byte fragments arrives whole")
def _(ctx):
    p, t = rosbridge(ctx)
    msg, data = publish_of_size(t, ctx.max_size - 7)
    p.fragments(TEXT, [msg[i:i + 1300] for i in range(0, len(msg), 1300)])
    expect_echo(p, t, data)


@case("9.x.5", "after a client is failed for size, other clients are still served")
def _(ctx):
    other, t = rosbridge(ctx)
    big, _ = rosbridge(ctx)
    msg, _ = publish_of_size(t, ctx.max_size * 2)
    big.text(msg)
    too_big(big)
    other.text(publish(t, "still served"))
    expect_echo(other, t, "still served", what=" (on a connection open meanwhile)")
    late, t2 = rosbridge(ctx)
    late.text(publish(t2, "new connection"))
    expect_echo(late, t2, "new connection", what=" (on a new connection)")


# === fleetlink.v1 (agent links): a subset

def varint(n: int) -> bytes:
    out = bytearray()
    while True:
        b = n & 0x7F
        n >>= 7
        out.append(b | (0x80 if n else 0))
        if not n:
            return bytes(out)


def lstr(s: str) -> bytes:
    b = s.encode()
    return varint(len(b)) + b


def read_varint(b: bytes, i: int) -> tuple[int, int]:
    n = shift = 0
    while True:
        x = b[i]
        i += 1
        n |= (x & 0x7F) << shift
        shift += 7
        if x < 0x80:
            return n, i


def read_str(b: bytes, i: int) -> tuple[str, int]:
    n, i = read_varint(b, i)
    return b[i:i + n].decode(), i + n


def hello(robot: str, token: str) -> bytes:
    """HELLO (docs/protocol.md 1.4): version 1, robot, token, heartbeat_ms, outbox_epoch.
    The longest heartbeat the hub allows, so that no heartbeat is due during a case."""
    body = varint(1) + lstr(robot) + lstr(token) + varint(60_000) + struct.pack("<Q", 0)
    return bytes([0x01]) + varint(len(body)) + body


def link_frames(msg: bytes) -> list[tuple[int, bytes]]:
    """The fleetlink.v1 frames (kind, body) back to back in one binary message."""
    out, i = [], 0
    while i < len(msg):
        kind = msg[i]
        n, i = read_varint(msg, i + 1)
        out.append((kind, msg[i:i + n]))
        i += n
    return out


def expect_link_frame(p: Peer, kind: int, name: str) -> bytes:
    while True:
        ev = p.next(what=f"a {name} frame")
        if ev.kind in ("close", "eof"):
            raise Fail(f"expected a {name} frame; the hub ended the link: {ev}")
        if ev.kind == "binary":
            for k, body in link_frames(ev.data):
                if k == kind:
                    return body


def agent(ctx: Ctx, welcome: bool = True, fragmented: bool = False) -> Peer:
    p = ctx.open(ctx.agent_url, subprotocols=[SUBPROTOCOL])
    if p.subprotocol != SUBPROTOCOL:
        raise Fail(f"RFC 6455 4.2.2: the hub must select the offered subprotocol {SUBPROTOCOL}; "
                   f"it answered {p.subprotocol!r}")
    if welcome:
        msg = hello(ctx.robot, ctx.robot_token)
        if fragmented:
            p.fragments(BINARY, [msg[:3], msg[3:20], msg[20:]])
        else:
            p.send(BINARY, msg)
        body = expect_link_frame(p, 0x02, "WELCOME")
        _session, i = read_str(body, 0)
        namespace, _ = read_str(body, i)
        if namespace != f"/{ctx.robot}":
            raise Fail(f"WELCOME names namespace {namespace!r}, expected /{ctx.robot}")
    return p


@case("A/5.3", "fleetlink.v1: HELLO in 3 binary fragments -> WELCOME; then a ping -> its pong")
def _(ctx):
    p = agent(ctx, fragmented=True)
    p.ping(b"agent ping")
    expect_pong(p, b"agent ping")


@case("A/2.1b", "fleetlink.v1: ping before HELLO -> pong (a ping is answered in any state)")
def _(ctx):
    p = agent(ctx, welcome=False)
    p.ping(b"before hello")
    expect_pong(p, b"before hello", "the pong to a ping sent before HELLO")


@case("A/text", "fleetlink.v1: a text message -> STATUS frame, the link stays up")
def _(ctx):
    p = agent(ctx)
    p.text("not a fleetlink.v1 frame")
    body = expect_link_frame(p, 0x0C, "STATUS")
    code, i = read_varint(body, 1)
    _alias, i = read_varint(body, i)
    text, _ = read_str(body, i)
    p.log.append(f"  (STATUS level {body[0]} code {code}: {text!r})")
    expect_alive(p)


@case("A/3.1", "fleetlink.v1: RSV1 on a binary frame after WELCOME -> close 1002")
def _(ctx):
    p = agent(ctx)
    p.send(BINARY, b"\x09\x10" + b"\x00" * 16, rsv=(True, False, False))
    protocol_error(p, "RFC 6455 5.2: a non-zero RSV bit without a negotiated extension")


@case("A/6.3.1", "fleetlink.v1: a text message that is not UTF-8 -> close 1007")
def _(ctx):
    p = agent(ctx)
    p.text(BAD_UTF8)
    invalid_utf8(p)


@case("A/1.x", "fleetlink.v1: an unmasked frame after WELCOME -> close 1002")
def _(ctx):
    p = agent(ctx)
    p.send(BINARY, b"\x09\x10" + b"\x00" * 16, mask=False)
    protocol_error(p, "RFC 6455 5.1: a server MUST close the connection on a frame that is not masked",
                   without_close=UNMASKED_CLOSE)


@case("A/7.1.1", "fleetlink.v1: close 1000 with a reason after WELCOME -> close answered, TCP closed")
def _(ctx):
    p = agent(ctx)
    p.close(1000, b"agent leaving")
    answered_close(p, 1000, "1000 'agent leaving'")


@case("A/7.1.1b", "fleetlink.v1: close before HELLO -> close answered, TCP closed")
def _(ctx):
    p = agent(ctx, welcome=False)
    p.close(1000, b"never mind")
    answered_close(p, 1000, "1000 'never mind', before HELLO")


# === running

def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rosbridge-url", required=True, help="ws://HOST:PORT/?token=OPERATOR_TOKEN")
    ap.add_argument("--agent-url", required=True, help="ws://HOST:PORT/")
    ap.add_argument("--robot", required=True)
    ap.add_argument("--robot-token", required=True)
    ap.add_argument("--max-message-size", type=int, required=True, help="the hub's --max-message-size")
    ap.add_argument("--only", help="run only cases whose label starts with this")
    args = ap.parse_args()
    ctx = Ctx(args)
    failed, ran, started = [], 0, time.monotonic()
    for label, title, fn in CASES:
        if args.only and not label.startswith(args.only):
            continue
        ran += 1
        t0 = time.monotonic()
        error = None
        try:
            fn(ctx)
        except Fail as e:
            error = str(e)
        except (Timeout, ServerError) as e:
            error = f"{type(e).__name__}: {e}"
        except Exception:  # the case itself broke: a failure too, with its traceback
            error = "the case raised:\n" + traceback.format_exc()
        ms = (time.monotonic() - t0) * 1000
        print(f"{'PASS' if error is None else 'FAIL'} {label:<10} {title} ({ms:.0f} ms)")
        if error is not None:
            failed.append(label)
            print(f"     {error}")
            for n, p in enumerate(ctx.peers):
                lines = p.log if len(p.log) <= 24 else p.log[:12] + ["  ..."] + p.log[-11:]
                print(f"     connection {n + 1}:")
                for line in lines:
                    print(f"       {line}")
        ctx.shut_all()
        sys.stdout.flush()
    took = time.monotonic() - started
    print(f"websocket conformance: {ran} cases, {ran - len(failed)} passed, {len(failed)} failed ({took:.1f} s)")
    if failed:
        print(f"failed: {' '.join(failed)}")
    return 1 if failed or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
