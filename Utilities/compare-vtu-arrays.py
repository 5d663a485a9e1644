# SPDX-License-Identifier: BSD-3-Clause
# Copyright (c) 2026 MMRep developers (see LICENSE)
# Decodes every DataArray of two VTK XML .vtu files written by MMRep (appended raw, zlib, UInt64
# headers) and reports which arrays differ, by section and name:
#   python3 Utilities/compare-vtu-arrays.py a.vtu b.vtu
# (used to show that a model differs from another only by a new field).
import re, struct, sys, zlib

def arrays(path):
    data = open(path, 'rb').read()
    start = data.index(b'<AppendedData encoding="raw">')
    raw = data[data.index(b'_', start) + 1:]
    xml = data[:start].decode()
    out = {}
    section = None
    for line in xml.split('\n'):
        m = re.match(r'\s*<(FieldData|PointData|CellData|Points|Cells)\b', line)
        if m:
            section = m.group(1)
        m = re.search(r'<DataArray type="(\w+)" Name="([^"]*)".*?offset="(\d+)"', line)
        if not m:
            continue
        off = int(m.group(3))
        nb, bs, last = struct.unpack_from('<QQQ', raw, off)
        sizes = struct.unpack_from('<%dQ' % nb, raw, off + 24)
        p = off + 24 + 8 * nb
        payload = b''
        for s in sizes:
            payload += zlib.decompress(raw[p:p + s])
            p += s
        out[(section, m.group(2))] = (m.group(1), payload)
    return out

a, b = arrays(sys.argv[1]), arrays(sys.argv[2])
print('%s: %d arrays, %s: %d arrays' % (sys.argv[1], len(a), sys.argv[2], len(b)))
for key in sorted(set(a) | set(b)):
    if key not in a:
        print('only in %s: %s %s (%s, %d bytes)' % (sys.argv[2], key[0], key[1], b[key][0], len(b[key][1])))
    elif key not in b:
        print('only in %s: %s %s' % (sys.argv[1], key[0], key[1]))
    elif a[key] != b[key]:
        print('differs: %s %s' % key)
same = sum(1 for k in set(a) & set(b) if a[k] == b[k])
print('%d arrays identical (bytes of the decoded values)' % same)
