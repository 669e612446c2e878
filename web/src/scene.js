// @ts-check
// Drawing the scene on a canvas: the path, the turning space, the benches as rectangles, the
// handles, head and tail, speeds in colour, the first contact and the overlap past it, in the
// gallery's themes. World coordinates are metres, y up; a camera maps them to pixels.

/**
 * @typedef {{ cx: number, cy: number, k: number }} Camera  centre (m) and pixels per metre
 * @typedef {Record<string, any>} Theme  a theme's colours (assets/themes/*.toml)
 * @typedef {{
 *   handles: number, benches: number, data: Float64Array,
 *   headSpeed: number, turnRadius: number,
 *   path: { points: Float64Array, pieces: { from: number, to: number, colour: string }[] },
 *   gaps: DragonGaps | null,
 *   contact: { x: number, y: number, a: number, b: number, time: number } | null,
 *   t: number, selected: number, nearest: DragonNearest | null,
 *   speedColours: boolean, lang: Lang,
 * }} SceneData
 */

/**
 * Screen x, y of world point (x, y).
 * @param {Camera} cam @param {number} w @param {number} h @param {number} x @param {number} y
 * @returns {[number, number]}
 */
function toScreen(cam, w, h, x, y) {
  return [w / 2 + (x - cam.cx) * cam.k, h / 2 - (y - cam.cy) * cam.k];
}

/**
 * World x, y of screen point (sx, sy).
 * @param {Camera} cam @param {number} w @param {number} h @param {number} sx @param {number} sy
 * @returns {[number, number]}
 */
function toWorld(cam, w, h, sx, sy) {
  return [cam.cx + (sx - w / 2) / cam.k, cam.cy - (sy - h / 2) / cam.k];
}

/**
 * A colour of the speed ramp at fraction f (0..1), as rgb().
 * @param {string[]} ramp @param {number} f
 */
function rampColour(ramp, f) {
  const x = Math.min(1, Math.max(0, f)) * (ramp.length - 1);
  const i = Math.min(ramp.length - 2, Math.floor(x));
  const u = x - i;
  const a = hexRgb(ramp[i]);
  const b = hexRgb(ramp[i + 1]);
  return `rgb(${Math.round(a[0] + (b[0] - a[0]) * u)},${Math.round(a[1] + (b[1] - a[1]) * u)},${Math.round(a[2] + (b[2] - a[2]) * u)})`;
}

/** @param {string} hex "#rrggbb" or "#rrggbbaa" @returns {number[]} */
function hexRgb(hex) {
  return [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16));
}

/** "#rrggbbaa" as rgba(); "#rrggbb" as it is. @param {string} hex */
function cssColour(hex) {
  if (hex.length !== 9) return hex;
  const [r, g, b] = hexRgb(hex);
  return `rgba(${r},${g},${b},${(parseInt(hex.slice(7, 9), 16) / 255).toFixed(3)})`;
}

/**
 * The speed range the colours span: the frame's smallest to largest handle speed (by
 * magnitude), widened to at least 5 % of the head's speed so that a chain moving all at one
 * speed is one colour.
 * @param {SceneData} d @returns {[number, number]}
 */
function speedSpan(d) {
  let lo = Infinity, hi = -Infinity;
  for (let i = 0; i < d.handles; ++i) {
    const v = Math.abs(d.data[3 * i + 2]);
    lo = Math.min(lo, v);
    hi = Math.max(hi, v);
  }
  const min = 0.05 * d.headSpeed;
  if (hi - lo < min) {
    const mid = (hi + lo) / 2;
    lo = mid - min / 2;
    hi = mid + min / 2;
  }
  return [lo, hi];
}

/**
 * The backdrop: background, turning space, path. Drawn once per camera, theme and path.
 * @param {CanvasRenderingContext2D} ctx @param {number} w @param {number} h
 * @param {Camera} cam @param {Theme} th @param {SceneData} d
 */
function drawBackdrop(ctx, w, h, cam, th, d) {
  ctx.fillStyle = th.background;
  ctx.fillRect(0, 0, w, h);
  // The turning space.
  const [ox, oy] = toScreen(cam, w, h, 0, 0);
  ctx.beginPath();
  ctx.arc(ox, oy, d.turnRadius * cam.k, 0, 2 * Math.PI);
  ctx.fillStyle = cssColour(th.turning_fill);
  ctx.fill();
  ctx.setLineDash([6, 5]);
  ctx.strokeStyle = th.turning_space;
  ctx.lineWidth = 1.2;
  ctx.stroke();
  ctx.setLineDash([]);
  // The path, piece by piece (coil-in, S-curve, coil-out), clipped roughly to the view.
  const p = d.path.points;
  ctx.lineJoin = 'round';
  for (const piece of d.path.pieces) {
    ctx.beginPath();
    let pen = false;
    let lastX = NaN, lastY = NaN;
    for (let i = piece.from; i < piece.to; ++i) {
      const [sx, sy] = toScreen(cam, w, h, p[2 * i], p[2 * i + 1]);
      if (pen && Math.abs(sx - lastX) < 0.7 && Math.abs(sy - lastY) < 0.7 && i < piece.to - 1) continue;
      if (pen) ctx.lineTo(sx, sy);
      else ctx.moveTo(sx, sy);
      pen = true;
      lastX = sx;
      lastY = sy;
    }
    ctx.strokeStyle = piece.colour;
    ctx.lineWidth = piece.colour === th.s_curve ? 2 : 1;
    ctx.stroke();
  }
}

/**
 * The chain and its marks over the backdrop.
 * @param {CanvasRenderingContext2D} ctx @param {number} w @param {number} h
 * @param {Camera} cam @param {Theme} th @param {SceneData} d
 * @param {(key: string) => string} say
 */
function drawChain(ctx, w, h, cam, th, d, say) {
  const data = d.data;
  const hb = 3 * d.handles;  // benches start here
  const overlapping = new Set();
  if (d.gaps) for (const o of d.gaps.overlaps) { overlapping.add(o.a); overlapping.add(o.b); }
  const atContact = d.contact && Math.abs(d.t - d.contact.time) < 1e-6;
  if (atContact && d.contact) { overlapping.add(d.contact.a); overlapping.add(d.contact.b); }
  const [lo, hi] = d.speedColours ? speedSpan(d) : [0, 1];
  const outline = d.speedColours ? th.outline : th.outline;
  ctx.lineWidth = cam.k > 40 ? 1 : 0.6;
  ctx.lineJoin = 'miter';
  ctx.font = '600 13px system-ui, "Noto Sans CJK SC", sans-serif';
  ctx.textBaseline = 'middle';
  // Tail first, so the head is drawn on top where benches cross.
  for (let k = d.benches; k >= 1; --k) {
    const o = hb + 6 * (k - 1);
    const cx = data[o], cy = data[o + 1], ax = data[o + 2], ay = data[o + 3], hl = data[o + 4], hw = data[o + 5];
    const lx = ax * hl, ly = ay * hl, wx = -ay * hw, wy = ax * hw;
    const [x1, y1] = toScreen(cam, w, h, cx + lx + wx, cy + ly + wy);
    const [x2, y2] = toScreen(cam, w, h, cx + lx - wx, cy + ly - wy);
    const [x3, y3] = toScreen(cam, w, h, cx - lx - wx, cy - ly - wy);
    const [x4, y4] = toScreen(cam, w, h, cx - lx + wx, cy - ly + wy);
    if (Math.max(x1, x2, x3, x4) < 0 || Math.min(x1, x2, x3, x4) > w ||
        Math.max(y1, y2, y3, y4) < 0 || Math.min(y1, y2, y3, y4) > h) continue;
    ctx.beginPath();
    ctx.moveTo(x1, y1);
    ctx.lineTo(x2, y2);
    ctx.lineTo(x3, y3);
    ctx.lineTo(x4, y4);
    ctx.closePath();
    let fill;
    if (overlapping.has(k)) fill = th.collision;
    else if (d.speedColours) {
      const v = (Math.abs(data[3 * (k - 1) + 2]) + Math.abs(data[3 * k + 2])) / 2;
      fill = rampColour(th.speed_ramp, (v - lo) / (hi - lo));
    } else fill = k === 1 ? th.head : k === d.benches && k > 1 ? th.tail : th.body;
    ctx.fillStyle = fill;
    ctx.fill();
    ctx.strokeStyle = k === d.selected ? th.highlight : outline;
    ctx.lineWidth = k === d.selected ? 3 : cam.k > 40 ? 1 : 0.6;
    ctx.stroke();
  }
  // Handles, when they are large enough to see.
  const r = Math.max(1.2, 0.0275 * cam.k);
  if (cam.k > 12) {
    ctx.fillStyle = th.handle;
    ctx.beginPath();
    for (let i = 0; i < d.handles; ++i) {
      const [sx, sy] = toScreen(cam, w, h, data[3 * i], data[3 * i + 1]);
      if (sx < -5 || sx > w + 5 || sy < -5 || sy > h + 5) continue;
      ctx.moveTo(sx + r, sy);
      ctx.arc(sx, sy, r, 0, 2 * Math.PI);
    }
    ctx.fill();
  }
  // The overlap past the first contact, each pair's deepest point.
  if (d.gaps) {
    ctx.strokeStyle = th.contact;
    ctx.lineWidth = 1.5;
    for (const o of d.gaps.overlaps.slice(0, 20)) {
      const [sx, sy] = toScreen(cam, w, h, o.x, o.y);
      ctx.beginPath();
      ctx.moveTo(sx - 5, sy - 5); ctx.lineTo(sx + 5, sy + 5);
      ctx.moveTo(sx - 5, sy + 5); ctx.lineTo(sx + 5, sy - 5);
      ctx.stroke();
    }
  }
  // The first contact: a ring at its point, from shortly before it on.
  if (d.contact && d.t >= d.contact.time - 5 * (1 / d.headSpeed)) {
    const [sx, sy] = toScreen(cam, w, h, d.contact.x, d.contact.y);
    ctx.beginPath();
    ctx.arc(sx, sy, 9, 0, 2 * Math.PI);
    ctx.strokeStyle = atContact ? th.contact : th.collision;  // the touching benches are in the collision colour
    ctx.lineWidth = atContact ? 2.5 : 1.5;
    ctx.setLineDash(atContact ? [] : [3, 3]);
    ctx.stroke();
    ctx.setLineDash([]);
    label(ctx, [sx + 6, sy + 30], say('first_contact'), th.collision, th.background);  // below: the head's label is above
  }
  // Head and tail named (over the contact's ring).
  label(ctx, toScreen(cam, w, h, data[0], data[1]), say('head'), th.head, th.background);
  const n = d.handles - 1;
  if (n > 1) label(ctx, toScreen(cam, w, h, data[3 * n], data[3 * n + 1]), say('tail'), th.tail, th.background);
  // The followed bench's nearest neighbour.
  if (d.selected > 0 && d.nearest && d.nearest.bench > 0) {
    const o = hb + 6 * (d.selected - 1);
    const [ax, ay] = toScreen(cam, w, h, data[o], data[o + 1]);
    const [bx, by] = toScreen(cam, w, h, d.nearest.x, d.nearest.y);
    ctx.strokeStyle = th.highlight;
    ctx.lineWidth = 1.5;
    ctx.setLineDash([4, 3]);
    ctx.beginPath(); ctx.moveTo(ax, ay); ctx.lineTo(bx, by); ctx.stroke();
    ctx.setLineDash([]);
  }
  scaleBar(ctx, w, h, cam, th);
  if (d.speedColours) speedBar(ctx, w, h, th, lo, hi);
}

/**
 * A word with a halo, right of a point.
 * @param {CanvasRenderingContext2D} ctx @param {[number, number]} at @param {string} text
 * @param {string} colour @param {string} halo @param {CanvasTextAlign} [align]
 */
function label(ctx, at, text, colour, halo, align = 'left') {
  ctx.textAlign = align;
  ctx.lineWidth = 3;
  ctx.strokeStyle = halo;
  ctx.strokeText(text, at[0] + 7, at[1] - 9);
  ctx.fillStyle = colour;
  ctx.fillText(text, at[0] + 7, at[1] - 9);
  ctx.textAlign = 'left';
}

/**
 * A scale bar of a round length at the bottom left.
 * @param {CanvasRenderingContext2D} ctx @param {number} w @param {number} h @param {Camera} cam @param {Theme} th
 */
function scaleBar(ctx, w, h, cam, th) {
  const want = 90 / cam.k;  // metres in about 90 px
  const p = Math.pow(10, Math.floor(Math.log10(want)));
  const len = [1, 2, 5, 10].map((m) => m * p).filter((m) => m <= want).pop() ?? p;
  const px = len * cam.k;
  const x = 14, y = h - 16;
  ctx.strokeStyle = th.text;
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(x, y - 5); ctx.lineTo(x, y); ctx.lineTo(x + px, y); ctx.lineTo(x + px, y - 5);
  ctx.stroke();
  ctx.fillStyle = th.text;
  ctx.font = '12px system-ui, sans-serif';
  ctx.textBaseline = 'bottom';
  ctx.fillText(`${+len.toPrecision(3)} m`, x + 4, y - 4);
}

/**
 * The speed colours' key at the bottom right (the view's buttons are at the top).
 * @param {CanvasRenderingContext2D} ctx @param {number} w @param {number} h @param {Theme} th @param {number} lo @param {number} hi
 */
function speedBar(ctx, w, h, th, lo, hi) {
  const bw = 120, bh = 10, x = w - bw - 14, y = h - 36;
  const g = ctx.createLinearGradient(x, 0, x + bw, 0);
  th.speed_ramp.forEach((/** @type {string} */ c, /** @type {number} */ i) => g.addColorStop(i / (th.speed_ramp.length - 1), c));
  ctx.fillStyle = g;
  ctx.fillRect(x, y, bw, bh);
  ctx.strokeStyle = th.text;
  ctx.lineWidth = 1;
  ctx.strokeRect(x, y, bw, bh);
  ctx.fillStyle = th.text;
  ctx.font = '11px system-ui, sans-serif';
  ctx.textBaseline = 'top';
  ctx.textAlign = 'left';
  ctx.fillText(lo.toFixed(3), x, y + bh + 3);
  ctx.textAlign = 'right';
  ctx.fillText(`${hi.toFixed(3)} m/s`, x + bw, y + bh + 3);
  ctx.textAlign = 'left';
}

/**
 * Which bench (1..N) holds world point (x, y), the head's side first; 0 for none.
 * @param {SceneData} d @param {number} x @param {number} y @param {number} slack m
 */
function benchAt(d, x, y, slack) {
  const hb = 3 * d.handles;
  for (let k = 1; k <= d.benches; ++k) {
    const o = hb + 6 * (k - 1);
    const dx = x - d.data[o], dy = y - d.data[o + 1];
    const along = dx * d.data[o + 2] + dy * d.data[o + 3];
    const across = -dx * d.data[o + 3] + dy * d.data[o + 2];
    if (Math.abs(along) <= d.data[o + 4] + slack && Math.abs(across) <= d.data[o + 5] + slack) return k;
  }
  return 0;
}
