// The gutter's shading of a page, shared by the curled leaf (page.frag) and the flat page
// (flat_page.frag), so both darken the paper at the spine by the very same expression.

// Paper curves down into the binding: darker within a few percent of the width of the spine
// (beyond a quarter of the width the term is below 1/1000 and is skipped). A board stays flat: its
// hinge is a groove pressed in parallel to the spine, a shaded furrow with a lit lip beside it.
// s: distance from the spine, a fraction of the page width; gutter: 0 off, 1 paper, 2 a hard board.
float gutterLight(float light, float s, float gutter) {
    if (gutter > 1.5) {
        if (s < 0.12) {
            float groove = (s - 0.05) / 0.009;
            float lip = (s - 0.068) / 0.006;
            light *= 1.0 - 0.38 * exp(-groove * groove) + 0.12 * exp(-lip * lip);
        }
    } else if (gutter > 0.0 && s < 0.25) {
        light *= 1.0 - 0.22 * exp(-s / 0.045);
    }
    return light;
}
