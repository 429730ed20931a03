"""A Glossa checkpoint part (DIR/checkpoint/step_NNNNNN/rank_RRRR.cbor) in Python, for the
checkpoint fuzz: its frame (the 32-byte header, the CBOR state, the CRC-32 of both; doc/output.md,
"Checkpoints and --restart") taken apart and put back together, and the subset of CBOR that
nlohmann::json writes (maps with text keys, arrays, text, integers, floats of 16, 32 and 64
bits, booleans, null) decoded and encoded, so that a value can be edited and the part still
passes its CRC. Floats are encoded as 64 bits, which nlohmann reads back as the same doubles.
"""
import struct
import zlib

MAGIC = b"GLOSSACP"
HEADER = struct.Struct("<8sIIQQ")  # magic, format, rank, step, length of the CBOR


def unframe(data):
    """(rank, step, cbor) of a part's bytes; ValueError if the frame or its CRC is not intact."""
    magic, fmt, rank, step, length = HEADER.unpack_from(data)
    if magic != MAGIC or fmt != 1 or length != len(data) - HEADER.size - 4:
        raise ValueError("not an intact checkpoint frame")
    if zlib.crc32(data[:-4]) != struct.unpack("<I", data[-4:])[0]:
        raise ValueError("CRC mismatch")
    return rank, step, data[HEADER.size:-4]


def frame(rank, step, cbor):
    head = HEADER.pack(MAGIC, 1, rank, step, len(cbor)) + cbor
    return head + struct.pack("<I", zlib.crc32(head))


def _argument(data, at, info):
    if info < 24:
        return info, at
    size = {24: 1, 25: 2, 26: 4, 27: 8}[info]
    return int.from_bytes(data[at:at + size], "big"), at + size


def _decode(data, at):
    head = data[at]
    major, info = head >> 5, head & 31
    at += 1
    if major == 7:
        if info == 20:
            return False, at
        if info == 21:
            return True, at
        if info == 22:
            return None, at
        fmt, size = {25: (">e", 2), 26: (">f", 4), 27: (">d", 8)}[info]
        return struct.unpack(fmt, data[at:at + size])[0], at + size
    n, at = _argument(data, at, info)
    if major == 0:
        return n, at
    if major == 1:
        return -1 - n, at
    if major == 2:
        return bytes(data[at:at + n]), at + n
    if major == 3:
        return data[at:at + n].decode("utf-8"), at + n
    if major == 4:
        items = []
        for _ in range(n):
            item, at = _decode(data, at)
            items.append(item)
        return items, at
    if major == 5:
        d = {}
        for _ in range(n):
            key, at = _decode(data, at)
            d[key], at = _decode(data, at)
        return d, at
    raise ValueError(f"CBOR major type {major} is not written by nlohmann::json")


def decode(data):
    value, at = _decode(data, 0)
    if at != len(data):
        raise ValueError("trailing bytes after the CBOR value")
    return value


def _head(major, n):
    for limit, info, size in ((24, None, 0), (1 << 8, 24, 1), (1 << 16, 25, 2), (1 << 32, 26, 4), (1 << 64, 27, 8)):
        if n < limit:
            if info is None:
                return bytes([major << 5 | n])
            return bytes([major << 5 | info]) + n.to_bytes(size, "big")
    raise ValueError("integer too large for CBOR")


def encode(value):
    if value is False:
        return b"\xf4"
    if value is True:
        return b"\xf5"
    if value is None:
        return b"\xf6"
    if isinstance(value, int):
        return _head(0, value) if value >= 0 else _head(1, -1 - value)
    if isinstance(value, float):
        return b"\xfb" + struct.pack(">d", value)
    if isinstance(value, bytes):
        return _head(2, len(value)) + value
    if isinstance(value, str):
        raw = value.encode("utf-8")
        return _head(3, len(raw)) + raw
    if isinstance(value, list):
        return _head(4, len(value)) + b"".join(encode(v) for v in value)
    if isinstance(value, dict):
        return _head(5, len(value)) + b"".join(encode(k) + encode(v) for k, v in value.items())
    raise TypeError(f"cannot encode {type(value).__name__}")
