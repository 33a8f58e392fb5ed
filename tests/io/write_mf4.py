#!/usr/bin/env python3
"""Writes a logger's CSV as an ASAM MDF 4.10 file, with Python's standard library only: a second
writer, independent of mdflib (which `twin import` reads through and whose writer makes the other
MF4 fixtures), written from the MDF 4 block layout. tests/io/mdf_import_test.cpp runs it.

    write_mf4.py CSV OUT.mf4 --data dt|deflate|transposed [--split COL,...] [--units COL=UNIT,...] [--level 0-9]

Every column but the first becomes a 64-bit float channel (an empty cell: NaN), the first the time
master (seconds). --data: the records in one DT block, or in two DZ blocks (deflate, or
transposition + deflate) listed by a DL block under an HL block. --split: those columns go into a
second data group with its own master, sampled at every other row and the last. --level: zlib's
compression level of the DZ blocks (0: stored, the records' bytes as they are inside the stream).
"""
import argparse
import csv
import struct
import zlib


class Mf4:
    """The file's bytes; blocks are appended and linked by their offsets."""

    def __init__(self):
        self.buf = bytearray(64)

    def block(self, bid, links, data):
        at = len(self.buf)
        body = struct.pack("<%dQ" % len(links), *links) + data
        length = 24 + len(body)
        self.buf += b"##" + bid + b"\0\0\0\0" + struct.pack("<QQ", length, len(links)) + body
        self.buf += b"\0" * (-len(self.buf) % 8)  # blocks start on 8-byte boundaries
        return at

    def patch_link(self, block_at, index, value):
        struct.pack_into("<Q", self.buf, block_at + 24 + 8 * index, value)

    def tx(self, text, bid=b"TX"):
        data = text.encode("utf-8") + b"\0"
        return self.block(bid, [], data + b"\0" * (-len(data) % 8))


def records(rows):
    return b"".join(struct.pack("<%dd" % len(r), *r) for r in rows)


def transpose(data, columns):
    n = len(data) // columns
    whole = data[: n * columns]
    out = bytearray(len(whole))
    for c in range(columns):
        out[c * n:(c + 1) * n] = whole[c::columns]
    return bytes(out) + data[n * columns:]


def data_blocks(f, raw, record_size, kind, level):
    if kind == "dt":
        return f.block(b"DT", [], raw)
    half = (len(raw) // record_size // 2) * record_size  # two blocks, the first a whole number of records
    parts = [raw[:half], raw[half:]]
    dz = []
    for p in parts:
        zip_type = 1 if kind == "transposed" else 0
        z = zlib.compress(transpose(p, record_size) if zip_type else p, level)
        head = b"DT" + struct.pack("<BBIQQ", zip_type, 0, record_size if zip_type else 0, len(p), len(z))
        dz.append(f.block(b"DZ", [], head + z))
    dl = f.block(b"DL", [0] + dz, struct.pack("<B3xIQ", 1, len(dz), half))  # equal length: all but the last hold `half` bytes
    return f.block(b"HL", [dl], struct.pack("<HB5x", 0, 0))


def channel(f, name, unit, master, byte_offset):
    tx_name = f.tx(name)
    tx_unit = f.tx(unit) if unit else 0
    data = struct.pack("<BBBBIIIIBBH", 2 if master else 0, 1 if master else 0, 4, 0, byte_offset, 64, 0, 0, 0, 0, 0) + struct.pack("<6d", *[0.0] * 6)
    return f.block(b"CN", [0, 0, tx_name, 0, 0, 0, tx_unit, 0], data)


def group(f, name, times, columns, units, kind, level):
    """One data group with one channel group: the master, then the columns."""
    rows = [[t] + [c[1][i] for c in columns] for i, t in enumerate(times)]
    record_size = 8 * (1 + len(columns))
    cns = [channel(f, "Time", "s", True, 0)] + [channel(f, n, units.get(n, ""), False, 8 * (k + 1)) for k, (n, _) in enumerate(columns)]
    for a, b in zip(cns, cns[1:]):
        f.patch_link(a, 0, b)
    acq = f.tx(name)
    cg = f.block(b"CG", [0, cns[0], acq, 0, 0, 0], struct.pack("<QQHH4xII", 0, len(rows), 0, 0, record_size - 0, 0))
    data = data_blocks(f, records(rows), record_size, kind, level)
    return f.block(b"DG", [0, cg, data, 0], struct.pack("<B7x", 0))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("out")
    ap.add_argument("--data", choices=["dt", "deflate", "transposed"], default="dt")
    ap.add_argument("--split", default="")
    ap.add_argument("--units", default="")
    ap.add_argument("--level", type=int, default=-1)
    a = ap.parse_args()
    with open(a.csv, newline="") as fh:
        table = list(csv.reader(fh))
    header, body = table[0], [r for r in table[1:] if r]
    cols = [(h, [float(r[k]) if r[k] != "" else float("nan") for r in body]) for k, h in enumerate(header)]
    units = dict(u.split("=", 1) for u in a.units.split(",") if u)
    split = set(s for s in a.split.split(",") if s)
    f = Mf4()
    f.buf[0:64] = b"MDF     " + b"4.10    " + b"pywrite " + b"\0" * 4 + struct.pack("<H", 410) + b"\0" * 30 + struct.pack("<HH", 0, 0)
    hd = f.block(b"HD", [0, 0, 0, 0, 0, 0], struct.pack("<QhhBBBxdd", 1700000000 * 10**9, 0, 0, 2, 0, 0, 0.0, 0.0))
    md = f.tx("<FHcomment><TX>written by write_mf4.py</TX><tool_id>write_mf4.py</tool_id><tool_vendor>twin tests</tool_vendor>"
              "<tool_version>1</tool_version></FHcomment>", b"MD")
    fh_block = f.block(b"FH", [0, md], struct.pack("<Qhhb3x", 1700000000 * 10**9, 0, 0, 2))
    f.patch_link(hd, 1, fh_block)
    times = cols[0][1]
    main_cols = [c for c in cols[1:] if c[0] not in split]
    dgs = [group(f, "log", times, main_cols, units, a.data, a.level)]
    if split:
        keep = [i for i in range(len(times)) if i % 2 == 0 or i + 1 == len(times)]
        other = [(n, [v[i] for i in keep]) for n, v in cols[1:] if n in split]
        dgs.append(group(f, "slow", [times[i] for i in keep], other, units, a.data, a.level))
    for x, y in zip(dgs, dgs[1:]):
        f.patch_link(x, 0, y)
    f.patch_link(hd, 0, dgs[0])
    with open(a.out, "wb") as out:
        out.write(f.buf)


if __name__ == "__main__":
    main()
