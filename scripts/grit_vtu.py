"""Reading grit's output from Python helper scripts (Debian's python3-numpy only)."""
import pathlib
import re

import numpy as np


def read_vtu(path) -> dict:
    """The point arrays of a grit .vtu (appended raw data, UInt64 headers)."""
    raw = pathlib.Path(path).read_bytes()
    head, _, rest = raw.partition(b'<AppendedData encoding="raw">')
    data = rest[rest.index(b"_") + 1:]
    types = {"Float64": np.float64, "Int32": np.int32, "Int64": np.int64, "UInt8": np.uint8}
    out = {}
    for m in re.finditer(rb'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" format="appended" '
                         rb'offset="(\d+)"', head):
        kind, name, comps, offset = m.group(1).decode(), m.group(2).decode(), int(m.group(3)), int(m.group(4))
        size = int(np.frombuffer(data[offset:offset + 8], dtype=np.uint64)[0])
        values = np.frombuffer(data[offset + 8:offset + 8 + size], dtype=types[kind])
        out[name] = values.reshape(-1, comps) if comps > 1 else values
    return out
