# Hostile HDF5, EXR and TSV provenance (tests/bad/h5_hostile.cases): the
# attributes and datasets noiselab does not write, and records naming files.
# Sourced by tests/bad/fixtures.sh in the fixture folder, with $nl.
"$nl" synth fft --acf markov:scale=2 --size 16x16 --seed 2 -o hx_base.exr
"$nl" synth fft --acf markov:scale=4 --size 256 --seed 2 -o hx_base.tsv
/usr/bin/python3 - <<'PY'
import struct
import h5py, numpy as np

def field(name, data=None, **attrs):
    """A /field (16x16 float32 unless data) with the attributes given."""
    if data is None:
        data = np.random.default_rng(7).standard_normal((16, 16)).astype("f4")
    with h5py.File(name, "w") as f:
        d = f.create_dataset("field", data=data)
        for k, v in attrs.items():
            d.attrs[k] = v

vlen = h5py.string_dtype("utf-8")
ascii_vlen = h5py.string_dtype("ascii")
# attributes: arrays, shapes and types noiselab does not write
field("hx_model_arr.h5", model=np.array([b"markov:scale=4", b"gauss"]))
field("hx_model_varr.h5", model=np.array(["markov:scale=4", "gauss"], dtype=object).astype(vlen))
field("hx_flags_arr.h5", flags=np.array([b"a", b"b", b"c"]))
field("hx_origin_arr.h5", origin=np.array([b"1", b"2"]))
field("hx_spacing_arr.h5", spacing=np.array([b"1", b"2"]))
field("hx_size_arr.h5", size=np.array([b"16x16", b"16x16"]))
field("hx_seed_arr.h5", seed=np.array([b"1", b"2"]))
field("hx_method_arr.h5", method=np.array([b"fft", b"subdiv"]))
field("hx_version_arr.h5", version=np.array([b"1.0.0", b"9"]))
field("hx_model_arr1.h5", model=np.array([b"markov:scale=4"]))
field("hx_model_2d.h5", model=np.array([[b"a", b"b"], [b"c", b"d"]]))
field("hx_model_empty_arr.h5", model=np.array([], dtype="S8"))
field("hx_model_null.h5", model=h5py.Empty("S8"))
field("hx_model_long_fixed.h5", model=np.bytes_(b"markov:scale=4" + b" " * 2000))
field("hx_model_long_vlen.h5", model="markov:scale=4;" + "x" * 2000)
field("hx_seed_long.h5", seed="1" * 40)
field("hx_version_long.h5", version=np.bytes_(b"1" * 32))
field("hx_model_int.h5", model=np.int32(5))
field("hx_seed_int.h5", seed=np.int64(5))
field("hx_spacing_float.h5", spacing=np.array([0.5, 2.0]))
field("hx_spacing_float1.h5", spacing=np.float64(0.5))
field("hx_origin_float.h5", origin=np.float64(3.5))
field("hx_flags_compound.h5", flags=np.array((1, 2.0), dtype=[("a", "i4"), ("b", "f8")]))
field("hx_model_nonascii.h5", model=np.bytes_(b"markov:scale=4\xff"))
field("hx_flags_latin1.h5", flags=np.bytes_("clamped,caf\xe9".encode("latin-1")))
field("hx_flags_nul.h5", flags=np.bytes_(b"clamped\x00injected"))
field("hx_model_nul.h5", model=np.bytes_(b"markov:scale=4\x00;var=100"))
field("hx_flags_newline.h5", flags="clamped\nnoiselab: forged")
field("hx_method_esc.h5", method="fft\x1b[2J")
field("hx_processes_str.h5", processes="two")
field("hx_processes_arr.h5", processes=np.array([1, 2], dtype="i4"))
field("hx_processes_zero.h5", processes=np.int32(0))
field("hx_processes_float.h5", processes=np.float64(2.5))
with h5py.File("hx_model_bad_utf8.h5", "w") as f:
    d = f.create_dataset("field", data=np.ones((16, 16), "f4") * np.arange(16))
    t = h5py.h5t.C_S1.copy(); t.set_size(4); t.set_cset(h5py.h5t.CSET_UTF8)
    a = h5py.h5a.create(d.id, b"model", t, h5py.h5s.create(h5py.h5s.SCALAR))
    a.write(np.array(b"\xc3\x28\xa0\xa1", dtype="S4"), mtype=t)
# datasets noiselab does not write
field("hx_ds_compound.h5", np.zeros((8, 8), dtype=[("re", "f8"), ("im", "f8")]))
field("hx_ds_complex.h5", np.ones((8, 8), dtype="c16"))
field("hx_ds_string.h5", np.array([[b"1.5", b"2"], [b"3", b"4"]]))
field("hx_ds_vlen_str.h5", np.array([["1", "2"], ["3", "4"]], dtype=object).astype(vlen))
field("hx_ds_enum.h5", np.zeros((8, 8), dtype=h5py.enum_dtype({"a": 0, "b": 1}, basetype="i1")))
field("hx_ds_bool.h5", np.ones((8, 8), dtype=bool))
field("hx_ds_opaque.h5", np.zeros((8, 8), dtype="V4"))
with h5py.File("hx_ds_array.h5", "w") as f:
    h5py.h5d.create(f.id, b"field", h5py.h5t.array_create(h5py.h5t.NATIVE_DOUBLE, (2,)), h5py.h5s.create_simple((8,)))
with h5py.File("hx_ds_vlen.h5", "w") as f:
    d = f.create_dataset("field", (4,), dtype=h5py.vlen_dtype("f8"))
    for i in range(4):
        d[i] = np.arange(i + 1, dtype="f8")
with h5py.File("hx_ds_ref.h5", "w") as f:
    f["x"] = np.zeros(4)
    d = f.create_dataset("field", (4,), dtype=h5py.ref_dtype)
    for i in range(4):
        d[i] = f["x"].ref
# records naming files (synth --from must not read them unasked)
rec = dict(method="fft", seed="1", size="16x16", spacing="1,1", version="1.0.0")
field("hx_passwd.h5", model="image:/etc/passwd", **rec)
field("hx_image_here.h5", model="image:hx_base.exr", flags="clamped", **rec)
field("hx_image_missing.h5", model="image:/nonexistent/exemplar.exr", **rec)
field("hx_seedimg.h5", **dict(rec, model="markov:scale=4", size="32x32",
      method="subdiv:levels=1,neighborhood=2,tol=0.0001,periodic,seed-image|seed-image=/etc/passwd"))
field("hx_exemplar.h5", **dict(rec, model="",
      method="sparse:radius=16,cell=16,density=1|exemplar=/etc/passwd"))

def exr_attrs(src, dst, attrs):
    """src (a scanline EXR noiselab wrote) with attrs {name: (type, bytes)}
    set (None: removed); the offset table moved with the header."""
    b = open(src, "rb").read()
    at, order, vals = 8, [], {}
    while b[at] != 0:
        n = b.index(b"\0", at); t = b.index(b"\0", n + 1)
        size = struct.unpack_from("<i", b, t + 1)[0]
        name = b[at:n]
        order.append(name); vals[name] = (b[n + 1:t], b[t + 5:t + 5 + size])
        at = t + 5 + size
    end = at + 1
    x0, y0, x1, y1 = struct.unpack("<4i", vals[b"dataWindow"][1])
    for k, v in attrs.items():
        k = k.encode()
        if v is None:
            order.remove(k); del vals[k]
            continue
        if k not in vals:
            order.append(k)
        vals[k] = (v[0].encode(), v[1])
    head = b"".join(k + b"\0" + vals[k][0] + b"\0" + struct.pack("<i", len(vals[k][1])) + vals[k][1] for k in order)
    head = b[:8] + head + b"\0"
    lines = y1 - y0 + 1
    offs = struct.unpack_from("<%dQ" % lines, b, end)
    delta = len(head) - end
    out = head + struct.pack("<%dQ" % lines, *[o + delta for o in offs]) + b[end + 8 * lines:]
    open(dst, "wb").write(out)

S = lambda s: ("string", s)
exr_attrs("hx_base.exr", "hx_exr_model_int.exr", {"noiselab.model": ("int", struct.pack("<i", 5))})
exr_attrs("hx_exr_model_int.exr", "hx_exr_model_int.exr", {})
exr_attrs("hx_base.exr", "hx_exr_spacing_float.exr", {"noiselab.spacing": ("float", struct.pack("<f", 0.5))})
exr_attrs("hx_base.exr", "hx_exr_model_long.exr", {"noiselab.model": S(b"markov:scale=2;" + b"x" * 1500)})
exr_attrs("hx_base.exr", "hx_exr_seed_long.exr", {"noiselab.seed": S(b"1" * 40)})
exr_attrs("hx_base.exr", "hx_exr_model_nul.exr", {"noiselab.model": S(b"markov:scale=2\0;var=100")})
exr_attrs("hx_base.exr", "hx_exr_flags_ctrl.exr", {"noiselab.flags": S(b"clamped\nnoiselab: forged")})
exr_attrs("hx_base.exr", "hx_exr_spacing_inf.exr", {"noiselab.spacing": S(b"inf,1")})
exr_attrs("hx_base.exr", "hx_exr_spacing_junk.exr", {"noiselab.spacing": S(b"1,1junk")})
exr_attrs("hx_base.exr", "hx_exr_passwd.exr", {"noiselab.model": S(b"image:/etc/passwd")})
exr_attrs("hx_base.exr", "hx_exr_image_here.exr", {"noiselab.model": S(b"image:hx_base.tsv")})
exr_attrs("hx_base.exr", "hx_exr_seedimg.exr", {"noiselab.size": S(b"16x16"),
          "noiselab.method": S(b"subdiv:levels=1,neighborhood=2,tol=0.0001,periodic,seed-image|seed-image=/etc/passwd")})

# TSV records
t = open("hx_base.tsv").read()
open("hx_tsv_passwd.tsv", "w").write(t.replace("# model: markov:scale=4", "# model: image:/etc/passwd"))
open("hx_tsv_model_twice.tsv", "w").write(t.replace("# model: markov:scale=4",
                                                     "# model: markov:scale=4\n# model: image:/etc/passwd"))
open("hx_tsv_model_long.tsv", "w").write(t.replace("# model: markov:scale=4", "# model: markov:scale=4;" + "x" * 1500))
open("hx_tsv_flags_ctrl.tsv", "w").write(t.replace("# version:", "# flags: clamped\x1b[2J\n# version:"))
PY
