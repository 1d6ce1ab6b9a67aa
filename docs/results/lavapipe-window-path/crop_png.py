# crop_png.py IN OUT X Y W H: crops an 8-bit RGB/RGBA PNG (pure Python: no imaging library on this machine).
import struct, sys, zlib
def chunks(data):
    i = 8
    while i < len(data):
        n, = struct.unpack('>I', data[i:i+4]); t = data[i+4:i+8]; yield t, data[i+8:i+8+n]; i += 12 + n
src, dst = sys.argv[1], sys.argv[2]
x0, y0, w, h = map(int, sys.argv[3:7])
data = open(src, 'rb').read()
idat = b''
for t, c in chunks(data):
    if t == b'IHDR': W, H, depth, ctype = struct.unpack('>IIBB', c[:10])
    elif t == b'IDAT': idat += c
assert depth == 8 and ctype in (2, 6)
bpp = 4 if ctype == 6 else 3
raw = zlib.decompress(idat); stride = W * bpp; rows = []; prev = bytearray(stride); p = 0
for _ in range(H):
    f = raw[p]; line = bytearray(raw[p+1:p+1+stride]); p += 1 + stride
    for i in range(stride):
        a = line[i-bpp] if i >= bpp else 0; b = prev[i]; c = prev[i-bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line); prev = line
out = b''.join(b'\0' + bytes(r[x0*bpp:(x0+w)*bpp]) for r in rows[y0:y0+h])
def chunk(t, c): return struct.pack('>I', len(c)) + t + c + struct.pack('>I', zlib.crc32(t + c) & 0xffffffff)
open(dst, 'wb').write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, ctype, 0, 0, 0)) +
                      chunk(b'IDAT', zlib.compress(out, 9)) + chunk(b'IEND', b''))
