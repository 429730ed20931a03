"""Reads one rank's part of a Glossa checkpoint (CHECKPOINT/step_NNNNNN/rank_RRRR.cbor) into Python
values, for benchmarks that need state the CSV files do not carry (e.g. the contact multipliers).

The part is framed as src/io/output/CheckpointStore writes it: an 8-byte magic, format, rank, step
and the CBOR length (little endian, 32 bytes in all), the CBOR document nlohmann::json::to_cbor
wrote, then a CRC-32. Only the CBOR that nlohmann writes is decoded (definite lengths; integers,
floats, strings, byte strings, arrays, maps, true, false, null): Debian has no CBOR module for
/usr/bin/python3.
"""
import os
import struct

HEADER_BYTES = 32


def _argument(data, info, i):
    if info < 24:
        return info, i
    size = {24: 1, 25: 2, 26: 4, 27: 8}[info]
    return int.from_bytes(data[i:i + size], "big"), i + size


def _decode(data, i):
    major, info = data[i] >> 5, data[i] & 31
    i += 1
    if major == 7:
        floats = {25: (">e", 2), 26: (">f", 4), 27: (">d", 8)}
        if info in floats:
            fmt, size = floats[info]
            return struct.unpack(fmt, data[i:i + size])[0], i + size
        return {20: False, 21: True, 22: None}[info], i
    value, i = _argument(data, info, i)
    if major == 0:
        return value, i
    if major == 1:
        return -1 - value, i
    if major in (2, 3):
        raw = data[i:i + value]
        return (raw.decode() if major == 3 else raw), i + value
    if major == 4:
        items = []
        for _ in range(value):
            item, i = _decode(data, i)
            items.append(item)
        return items, i
    if major == 5:
        entries = {}
        for _ in range(value):
            key, i = _decode(data, i)
            entries[key], i = _decode(data, i)
        return entries, i
    raise ValueError(f"CBOR major type {major} at byte {i - 1} is not one nlohmann::json writes")


def latest_part(checkpoint_dir, rank=0):
    """The latest step's part of the given rank, as a dict."""
    with open(os.path.join(checkpoint_dir, "latest")) as f:
        step = f.read().strip()
    with open(os.path.join(checkpoint_dir, step, f"rank_{rank:04d}.cbor"), "rb") as f:
        data = f.read()
    length = int.from_bytes(data[24:32], "little")
    return _decode(data[HEADER_BYTES:HEADER_BYTES + length], 0)[0]
