"""What students see (edition.display): numbers in math without raw e-notation, round-off as 0 or a bound, raw
Python output found, pictures with alt text."""

from __future__ import annotations

import base64
from unittest import mock

import numpy as np
import pytest

from edition import display as DP


@pytest.mark.parametrize(
    "value,kw,want",
    [
        (2.88e-16, {}, "0"),
        (-3e-15, {}, "0"),
        (2.88e-16, {"as_bound": True}, "< 10^{-12}"),
        (4.93e-7, {}, r"4.93\times10^{-7}"),
        (1.2098e4, {}, r"1.21\times10^{4}"),
        (0.50332, {}, "0.503"),
        (3e-7, {"scale": 1e6}, "0"),
        (3e-7, {"scale": 1.0}, r"3.00\times10^{-7}"),
        (np.inf, {}, r"\infty"),
    ],
)
def test_tex_never_writes_e_notation(value, kw, want):
    got = DP.tex(value, **kw)
    assert got == want and not DP.raw_output(f"${got}$")


def test_tex_rejects_a_bad_scale():
    with pytest.raises(ValueError, match="scale"):
        DP.tex(1.0, scale=0)


@pytest.mark.parametrize(
    "text,found",
    [
        ("$|\\det J| = 2.88e-16$", ["2.88e-16"]),
        ("rank [6]", ["[6]"]),
        ("{d3x: 0.5}", ["{d3x: "]),
        ("{'pair-13', 'x'}", ["{'pair-13',"]),
        ("array([1, 2])", ["array("]),
        ("kappa = 1.21e+04", ["1.21e+04"]),
        (r"$4.9\times10^{-11}$, $[0, 1]$, $\mathbf J_{[1]}$, $\{x: x > 0\}$, [Figure 7](#f7)", []),
    ],
)
def test_raw_output_is_found_and_mathematics_is_not(text, found):
    assert DP.raw_output(text) == found


def test_an_image_carries_its_alt_text_for_jupyterlab_html_and_plain_readers():
    got = []
    png = b"\x89PNG\r\n\x1a\nfake"
    with mock.patch("IPython.display.display", lambda *a, **k: got.append((a, k))):
        DP.image(png, 'Three wheels & a "centre"', width=300, metadata={"wmr_figure": "fig07"})
    (bundle,), kw = got[0]
    assert kw["raw"] and kw["metadata"]["wmr_figure"] == "fig07"
    tag = bundle["text/html"]
    assert 'alt="Three wheels &amp; a &quot;centre&quot;"' in tag and 'width="300"' in tag
    assert base64.b64decode(bundle["image/png"]) == png and bundle["text/plain"] == 'Three wheels & a "centre"'
    with pytest.raises(ValueError, match="alt"):
        DP.image(png, "  ")
