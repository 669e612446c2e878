"""Pictures and films from Python are the tool's: the same bytes as dragon render writes, the
same pixels decoded, the same clip as dragon video makes."""

import struct
import zlib

import numpy as np
import pytest

import benchdragon as bd


def png_pixels(data: bytes) -> np.ndarray:
    """An 8-bit RGB PNG (what Cairo writes for an opaque picture) decoded: (H, W, 3)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, chunks, header = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            chunks.append(body)
        pos += 12 + length
    width, height, depth, colour = header[:4]
    assert depth == 8 and colour == 2
    raw = zlib.decompress(b"".join(chunks))
    stride = 3 * width
    out = np.zeros((height, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        row = np.zeros(stride, dtype=np.int32)
        for x in range(stride):
            a = row[x - 3] if x >= 3 else 0
            b = prev[x]
            c = prev[x - 3] if x >= 3 else 0
            if kind == 0:
                p = 0
            elif kind == 1:
                p = a
            elif kind == 2:
                p = b
            elif kind == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            row[x] = (line[x] + p) & 255
        out[y], prev = row, row
    return out.reshape(height, width, 3).astype(np.uint8)


@pytest.mark.parametrize("args,kwargs", [
    (["--time", "300"], {"t": 300}),
    (["--collision", "--zoom", "4", "--legend"], {"collision": True, "zoom": 4, "legend": True}),
    (["--time", "100", "--speed-colours", "--theme", "dark"], {"t": 100, "speed_colours": True, "theme": "dark"}),
])
def test_png_is_the_tools_file(dragon, tmp_path, args, kwargs):
    out = tmp_path / "tool.png"
    dragon("render", *args, "--size", "320x240", "-o", str(out), "--quiet")
    mine = bd.render(size=(320, 240), **kwargs)
    assert mine.data == out.read_bytes()
    assert mine._repr_png_() == mine.data and mine._repr_svg_() is None


def test_pixels_are_the_pngs():
    pic = bd.render(t=250, size=(48, 40), speed_colours=True)
    rgba = pic.to_numpy()
    assert rgba.shape == (40, 48, 4) and rgba.dtype == np.uint8
    assert (rgba[:, :, 3] == 255).all()
    np.testing.assert_array_equal(rgba[:, :, :3], png_pixels(pic.data))


def test_svg_and_pdf(tmp_path):
    svg = bd.render(t=10, format="svg", size=(200, 100))
    assert svg._repr_svg_().startswith("<?xml") and 'width="200px"' in svg._repr_svg_()
    pdf = bd.render(bd.Scenario(pitch=0.6), t=10, format="pdf", size=(200, 100))
    assert pdf.data.startswith(b"%PDF-") and b"/MediaBox [ 0 0 150 75 ]" in pdf.data
    pdf.save(tmp_path / "f.pdf")
    assert (tmp_path / "f.pdf").read_bytes() == pdf.data


def test_pictures_refuse_as_the_tool_does():
    with pytest.raises(bd.InputError):
        bd.render(t=10, size=(8, 8))
    with pytest.raises(bd.InputError) as e:
        bd.render(t=10, format="jpeg")
    assert e.value.field == "format"
    with pytest.raises(bd.InputError) as e:
        bd.render(t=10, zoom=-1)
    assert e.value.field == "zoom"
    with pytest.raises(bd.InputError):
        bd.render()  # neither a time nor the collision


def test_a_clip_is_the_tools(dragon, tmp_path):
    # The same plan: its frame count and length say so (the encoders are the same code).
    mine = bd.video(out=tmp_path / "py.gif", from_=400, size=(160, 120), progress=False)
    done = dragon("video", "--from", "400", "--size", "160x120", "-o", str(tmp_path / "tool.gif"))
    assert f"{mine['frames']} frames" in done.stderr
    assert (tmp_path / "py.gif").read_bytes() == (tmp_path / "tool.gif").read_bytes()
    with pytest.raises(bd.InputError) as e:
        bd.video(out=tmp_path / "x.mp4", to="sideways", progress=False)
    assert e.value.field == "to"
    assert not (tmp_path / "x.mp4").exists()


def test_a_storyboards_poster(dragon, tmp_path):
    board = bd.ASSETS + "/films/contest.toml"
    bd.film(board, tmp_path / "py.png", at=2.0, size=(320, 180), progress=False)
    dragon("film", board, "--at", "2", "--size", "320x180", "-o", str(tmp_path / "tool.png"), "--quiet")
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "tool.png").read_bytes()


def test_chinese_words_as_the_tool_draws_them(dragon, tmp_path):
    dragon("render", "--collision", "--zoom", "4", "--legend", "--lang", "zh", "--size", "320x240", "-o",
           str(tmp_path / "zh.png"), "--quiet")
    zh = bd.render(collision=True, zoom=4, legend=True, lang="zh", size=(320, 240))
    assert zh.data == (tmp_path / "zh.png").read_bytes()
    assert zh.data != bd.render(collision=True, zoom=4, legend=True, size=(320, 240)).data
    with pytest.raises(bd.InputError) as e:
        bd.render(t=10, lang="fr")
    assert e.value.field == "lang"


@pytest.mark.parametrize("flags,kwargs", [
    (["--print", "column"], {"print_size": "column"}),
    (["--width-cm", "12", "--font-pt", "9", "--dpi", "150"], {"width_cm": 12, "font_pt": 9, "dpi": 150}),
])
def test_print_sizes_as_the_tool_draws_them(dragon, tmp_path, flags, kwargs):
    import re

    for ext in ("png", "svg"):
        out = tmp_path / f"tool.{ext}"
        dragon("render", "--time", "300", "--size", "1600x1200", *flags, "-o", str(out), "--quiet")
        mine = bd.render(t=300, size=(1600, 1200), format=ext, **kwargs)
        if ext == "png":
            assert mine.data == out.read_bytes()
            assert b"pHYs" in mine.data
            assert mine.to_numpy().shape[:2] == (mine.size[1], mine.size[0])
        else:  # Cairo numbers its surfaces process-wide
            same = lambda b: re.sub(rb"surface[0-9]+", b"surface", b)  # noqa: E731
            assert same(mine.data) == same(out.read_bytes())
    with pytest.raises(bd.InputError) as e:
        bd.render(t=300, print_size="poster")
    assert e.value.field == "print_size"
    with pytest.raises(bd.InputError) as e:
        bd.render(t=300, font_pt=0.5)
    assert e.value.field == "font_pt"


@pytest.mark.parametrize("format", ["png", "svg", "pdf"])
def test_save_refuses_a_name_of_another_format(tmp_path, format):
    # As the tool refuses `render -o y.png` for anything but a PNG: the name says the format.
    pic = bd.render(t=10, format=format, size=(64, 48))
    for ext in ["png", "svg", "pdf", "jpg", ""]:
        if ext == format:
            continue
        name = tmp_path / (f"y.{ext}" if ext else "y")
        with pytest.raises(bd.InputError) as e:
            pic.save(name)
        assert e.value.field == "path"
        assert str(name) in e.value.value
        assert f".{format}" in e.value.allowed
        assert "\n" not in str(e.value)
        assert not name.exists() and list(tmp_path.iterdir()) == []
    pic.save(tmp_path / f"y.{format.upper()}")  # extensions are matched as the tool matches them
    assert (tmp_path / f"y.{format.upper()}").read_bytes() == pic.data


# The look and the encoder are the library's requests (dragon/look.hpp, EncoderRequest): the
# tool and Python refuse the same asks, each naming the same key.
@pytest.mark.parametrize("flags, keywords, field", [
    (["--time", "10", "--centre", "1", "2"], {"t": 10, "centre": (1, 2)}, "centre"),
    (["--time", "10", "--zoom", "1e-12"], {"t": 10, "zoom": 1e-12}, "zoom"),
    (["--time", "10", "--zoom", "1e-9", "--follow-head"], {"t": 10, "zoom": 1e-9, "follow_head": True}, "zoom"),
])
def test_render_refuses_what_the_tool_refuses(dragon, tmp_path, flags, keywords, field):
    done = dragon("render", *flags, "--size", "1280x720", "-o", str(tmp_path / "x.png"), check=False)
    assert done.returncode == 2, done.stderr
    assert f"--{field.replace('_', '-')} " in done.stderr, done.stderr
    with pytest.raises(bd.InputError) as e:
        bd.render(size=(1280, 720), **keywords).save(str(tmp_path / "y.png"))
    assert e.value.field == field


@pytest.mark.parametrize("out, flags, keywords, field", [
    ("v.webm", ["--preset", "fast"], {"preset": "fast"}, "preset"),
    ("v.gif", ["--tune", "film"], {"tune": "film"}, "tune"),
    ("v.mp4", ["--colours", "32"], {"colours": 32}, "colours"),
    ("v.mp4", ["--zoom", "1e-9", "--follow-head"], {"zoom": 1e-9, "follow_head": True}, "zoom"),
])
def test_video_refuses_what_the_tool_refuses(dragon, tmp_path, out, flags, keywords, field):
    done = dragon("video", "--to", "2", *flags, "-o", str(tmp_path / ("tool-" + out)), "-q", check=False)
    assert done.returncode == 2, done.stderr
    assert f"--{field.replace('_', '-')} " in done.stderr, done.stderr
    with pytest.raises(bd.InputError) as e:
        bd.video(out=str(tmp_path / out), to=2, progress=False, **keywords)
    assert e.value.field == field
    assert not (tmp_path / out).exists() and not (tmp_path / ("tool-" + out)).exists()
