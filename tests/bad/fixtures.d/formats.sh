# Hostile field files for tests/bad/formats.cases: .npy headers that lie
# (truncated, a huge shape, an integer dtype, Fortran order, too few bytes)
# and a 16-bit PNG with a noiselab text chunk but no noiselab.range.
/usr/bin/python3 - <<'PY'
import struct, zlib

def npy(name, header, data=b""):
    h = header.encode()
    h += b" " * ((-(10 + len(h) + 1)) % 64) + b"\n"
    with open(name, "wb") as f:
        f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", len(h)) + h + data)

npy("huge.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (4000000000, 4000000000), }")
npy("int.npy", "{'descr': '<i4', 'fortran_order': False, 'shape': (4, 4), }", b"\0" * 64)
npy("fortran.npy", "{'descr': '<f8', 'fortran_order': True, 'shape': (4, 4), }", b"\0" * 128)
npy("short.npy", "{'descr': '<f8', 'fortran_order': False, 'shape': (4, 4), }", b"\0" * 100)
with open("trunc.npy", "wb") as f:  # the header claims 118 bytes; 20 follow
    f.write(b"\x93NUMPY\x01\x00" + struct.pack("<H", 118) + b"{'descr': '<f8', 'fo")

def chunk(t, d):
    return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)

rows = b"".join(b"\0" + struct.pack(">4H", 0, 1000 * y, 30000, 65535) for y in range(4))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 4, 4, 16, 0, 0, 0, 0))
       + chunk(b"tEXt", b"noiselab.seed\x007") + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))
with open("norange.png", "wb") as f:
    f.write(png)
with open("badrange.png", "wb") as f:
    f.write(png.replace(chunk(b"tEXt", b"noiselab.seed\x007"), chunk(b"tEXt", b"noiselab.range\x003,1")))
PY
