"""Loads HTML pages in Debian's headless Chromium: each page is screenshotted (the PNG decoded
and required to show more than one colour), and a copy with a small script appended reports
through --dump-dom whether every image decoded and whether anything overflows its box."""
import json, os, re, struct, subprocess, tempfile, zlib

FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync"]

PROBE = """<script>
window.addEventListener('load', function () {
  var imgs = Array.prototype.slice.call(document.images);
  var broken = imgs.filter(function (i) { return !(i.complete && i.naturalWidth > 0); }).length;
  var boxes = Array.prototype.slice.call(document.querySelectorAll('td,th,p,h1,h2,figure,table'));
  var over = boxes.filter(function (e) { return e.scrollWidth > e.clientWidth + 1 && e.tagName != 'TABLE'; }).length;
  var pre = document.createElement('pre');
  pre.id = 'sl-probe';
  pre.textContent = JSON.stringify({images: imgs.length, broken: broken, overflowing: over,
      pageWider: document.documentElement.scrollWidth > window.innerWidth,
      links: Array.prototype.slice.call(document.links).map(function (a) { return a.getAttribute('href'); })});
  document.body.appendChild(pre);
});
</script>"""


def chromium(args, timeout=120):
    with tempfile.TemporaryDirectory() as profile:
        return subprocess.run(["chromium"] + FLAGS + ["--user-data-dir=" + profile] + args,
                              capture_output=True, text=True, timeout=timeout)


def png_colours(path):
    """Decodes an 8-bit RGB(A) PNG (what Chromium writes) and counts its distinct pixels."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path + ": not a PNG"
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            channels = {2: 3, 6: 4}[colour]
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = 1 + width * channels
    assert len(raw) == stride * height, path + ": truncated image data"
    seen = set()
    for row in range(0, height, max(1, height // 64)):  # filtered bytes: enough to tell blank from not
        line = raw[row * stride + 1:(row + 1) * stride]
        for x in range(0, len(line), channels * max(1, width // 64)):
            seen.add(line[x:x + channels])
    return width, height, len(seen)


def check_page(path, shot, width=1100):
    """Returns the probe's findings for `path` and writes its screenshot to `shot`."""
    chromium(["--screenshot=" + shot, "--window-size=%d,1600" % width, "file://" + os.path.abspath(path)])
    assert os.path.getsize(shot) > 0, shot + ": no screenshot"
    w, h, colours = png_colours(shot)
    html = open(path, encoding="utf-8").read()
    probe_path = path + ".probe.html"
    with open(probe_path, "w", encoding="utf-8") as f:
        f.write(html.replace("</body>", PROBE + "</body>"))
    try:
        out = chromium(["--dump-dom", "--virtual-time-budget=5000", "--window-size=%d,1600" % width,
                        "file://" + os.path.abspath(probe_path)]).stdout
    finally:
        os.remove(probe_path)
    m = re.search(r'<pre id="sl-probe">(.*?)</pre>', out, re.S)
    assert m, path + ": the probe did not run (page not loaded?)"
    found = json.loads(m.group(1).replace("&quot;", '"').replace("&amp;", "&"))
    found["screenshot"] = {"width": w, "height": h, "colours": colours}
    return found
