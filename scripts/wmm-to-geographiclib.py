#!/usr/bin/env python3
"""Converts NOAA's World Magnetic Model coefficients into GeographicLib's model files.

GeographicLib::MagneticModel reads NAME.wmm (text metadata, "WMMF-1") and NAME.wmm.cof
(an 8-character ID, then for the main field and for its secular variation: N and M as
4-byte little-endian ints, the cosine coefficients g(n,m) for m = 0..M, n = m..N, then
the sine coefficients h(n,m) for m = 1..M, n = m..N, as little-endian doubles).

Input: the JSON form of NOAA's WMM.COF (keys main_field_coeff_g/h, secular_var_coeff_g/h,
indexed n(n+1)/2 + m, n_max, epoch, name, start_date), e.g. wmm-2020.json.
Usage: wmm-to-geographiclib.py OUTDIR INPUT.json...
The coefficients are NOAA's (public domain): https://www.ncei.noaa.gov/products/world-magnetic-model
"""
import json
import os
import struct
import sys


def index(n, m):
    return n * (n + 1) // 2 + m


def coefficients(g, h, n_max):
    cos = [g[index(n, m)] for m in range(n_max + 1) for n in range(m, n_max + 1)]
    sin = [h[index(n, m)] for m in range(1, n_max + 1) for n in range(m, n_max + 1)]
    return struct.pack("<ii", n_max, n_max) + struct.pack("<%dd" % len(cos), *cos) + \
        struct.pack("<%dd" % len(sin), *sin)


def convert(path, outdir):
    with open(path) as f:
        d = json.load(f)
    n_max = int(d["n_max"])
    if int(d["n_max_sec_var"]) != n_max:
        raise SystemExit("%s: expected the secular variation to the main field's degree" % path)
    for key in ("main_field_coeff_g", "main_field_coeff_h", "secular_var_coeff_g",
                "secular_var_coeff_h"):
        if len(d[key]) != index(n_max, n_max) + 1:
            raise SystemExit("%s: %s: expected %d coefficients" % (path, key, index(n_max, n_max) + 1))
    epoch = float(d["epoch"])
    label = d["name"].replace("-", "").lower()  # WMM-2015v2 -> wmm2015v2
    ident = (d["name"].replace("-", "").upper().replace("V2", "B") + "AAAAAAAA")[:8]
    if ident[7] not in "AB":
        ident = ident[:7] + "A"
    meta = "\n".join([
        "WMMF-1",
        "# Converted by scripts/wmm-to-geographiclib.py from NOAA's published coefficients",
        "# (World Magnetic Model, public domain, https://www.ncei.noaa.gov/products/world-magnetic-model)",
        "Name            %s" % label,
        "Description     World Magnetic Model %s" % d["name"],
        "URL             https://www.ncei.noaa.gov/products/world-magnetic-model",
        "Publisher       National Oceanic and Atmospheric Administration",
        "ReleaseDate     %s" % d["start_date"][:10],
        "Radius          6371200",
        "NumModels       1",
        "Epoch           %g" % epoch,
        "DeltaEpoch      5",
        "MinTime         %g" % epoch,
        "MaxTime         %g" % (epoch + 5),
        "MinHeight       -1000",
        "MaxHeight       850000",
        "Normalization   Schmidt",
        "ByteOrder       little",
        "ID              %s" % ident,
        "",
    ])
    base = os.path.join(outdir, label + ".wmm")
    with open(base, "w") as f:
        f.write(meta)
    with open(base + ".cof", "wb") as f:
        f.write(ident.encode("ascii"))
        f.write(coefficients(d["main_field_coeff_g"], d["main_field_coeff_h"], n_max))
        f.write(coefficients(d["secular_var_coeff_g"], d["secular_var_coeff_h"], n_max))
    print("%s -> %s (ID %s, %g to %g)" % (path, base, ident, epoch, epoch + 5))


def main():
    if len(sys.argv) < 3:
        raise SystemExit("usage: wmm-to-geographiclib.py OUTDIR INPUT.json...")
    for path in sys.argv[2:]:
        convert(path, sys.argv[1])


if __name__ == "__main__":
    main()
