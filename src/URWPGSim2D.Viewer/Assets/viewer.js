// URWPGSim2D match viewer: replays a recorded match (data inline in the page) or follows a live
// match streamed by the server (Server-Sent Events). World units are mm, +X right, +Z down.
(function () {
  'use strict';

  const TEAM_COLOURS = ['#d9483b', '#2f6fd6', '#2e9e5b', '#9b51c9'];
  const BALL_COLOUR = '#f29b30';
  const SPEEDS = [0.25, 0.5, 1, 2, 4, 8, 16];
  const CYCLE_SECONDS = 0.1;
  const TRAIL_CYCLES = 60;
  const MARGIN_MM = 60;
  const FOLLOW_ZOOM = 2.5;
  const STRIDE_FISH = 6; // x, z, heading, joint 1..3
  const STRIDE_BALL = 2; // x, z
  const MOTION_FISH = 2, MOTION_BALL = 2; // speed, angular speed / vx, vz
  const CODES_FISH = 4; // VCode, TCode, speed gear, turn gear (255: none)
  const NO_CODE = 255;

  // ---- The fish model: the eight leaf polygons of docs/fish.md, exactly as the library builds them.
  // Leaves in FishPart order; each is a list of frame points (a forward, b to the fish's right) in
  // frame 0 (body) or frame i = tail segment i.
  const LEAF_FRAMES = [0, 0, 0, 1, 2, 3, 3, 3];
  function localLeaves(size) {
    const l = size.length, hw = size.width / 2, head = size.head;
    const l1 = size.joints[0], l2 = size.joints[1], l3 = size.joints[2];
    const left = [[-7 * l / 24, -hw - 37.5], [-7 * l / 24, -hw - 25], [-l / 12, -hw], [l / 4, -hw]];
    const segment = (len, start, end) => [[0, start * len], [0, -start * len], [-len, -end * len], [-len, end * len]];
    const end3 = 0.089964 * l3;
    return [
      left,
      [[l / 2, -hw], [l / 2 + head, 0], [l / 2, hw], [-l / 2, hw], [-l / 2, -hw]],
      left.map(p => [p[0], -p[1]]),
      segment(l1, 0.266112, 0.2193408),
      segment(l2, 0.231336, 0.14994),
      segment(l3, 0.115668, 0.089964),
      [[-2 * l3, -50], [-1.8 * l3, -10], [-l3, end3]],
      [[-1.8 * l3, 35], [-1.8 * l3, -10], [-l3, -end3]],
    ];
  }

  // World polygons [[x, z], ...] of the eight leaves at pose (x, z, heading, φ1, φ2, φ3).
  function leaves(size, x, z, heading, j1, j2, j3, local) {
    local = local || localLeaves(size);
    const joints = [j1, j2, j3], seg = size.joints;
    const ox = [x], oz = [z], ang = [heading];
    let sx = x - size.length / 2 * Math.cos(heading), sz = z - size.length / 2 * Math.sin(heading);
    for (let i = 0; i < 3; i++) {
      const a = heading + joints[i];
      ox.push(sx); oz.push(sz); ang.push(a);
      sx -= seg[i] * Math.cos(a); sz -= seg[i] * Math.sin(a);
    }
    const out = [];
    for (let k = 0; k < 8; k++) {
      const f = LEAF_FRAMES[k], c = Math.cos(ang[f]), s = Math.sin(ang[f]);
      out.push(local[k].map(p => [ox[f] + p[0] * c - p[1] * s, oz[f] + p[0] * s + p[1] * c]));
    }
    return out;
  }

  // The 8-DOP of a polygon (extreme projections on x, z and the two diagonals) as an octagon.
  function kdop(poly) {
    const r = Math.SQRT1_2;
    let x0 = Infinity, x1 = -Infinity, z0 = Infinity, z1 = -Infinity, d0 = Infinity, d1 = -Infinity, e0 = Infinity, e1 = -Infinity;
    for (const [x, z] of poly) {
      x0 = Math.min(x0, x); x1 = Math.max(x1, x); z0 = Math.min(z0, z); z1 = Math.max(z1, z);
      const d = (x + z) * r, e = (x - z) * r;
      d0 = Math.min(d0, d); d1 = Math.max(d1, d); e0 = Math.min(e0, e); e1 = Math.max(e1, e);
    }
    let shape = [[x0, z0], [x1, z0], [x1, z1], [x0, z1]];
    const clip = (nx, nz, limit) => { // keep n·p <= limit
      const res = [];
      for (let i = 0; i < shape.length; i++) {
        const p = shape[i], q = shape[(i + 1) % shape.length];
        const dp = p[0] * nx + p[1] * nz - limit, dq = q[0] * nx + q[1] * nz - limit;
        if (dp <= 0) res.push(p);
        if ((dp < 0) !== (dq < 0) && dp !== dq) { const t = dp / (dp - dq); res.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]); }
      }
      shape = res;
    };
    clip(r, r, d1); clip(-r, -r, -d0); clip(r, -r, e1); clip(-r, r, -e0);
    return shape;
  }

  // Minimum enclosing circle of points (incremental, exact for small sets).
  function enclosingCircle(points) {
    const circle2 = (a, b) => { const cx = (a[0] + b[0]) / 2, cz = (a[1] + b[1]) / 2; return [cx, cz, Math.hypot(a[0] - cx, a[1] - cz)]; };
    const circle3 = (a, b, c) => {
      const bx = b[0] - a[0], bz = b[1] - a[1], cx = c[0] - a[0], cz = c[1] - a[1], d = 2 * (bx * cz - bz * cx);
      if (Math.abs(d) < 1e-12) return null;
      const ux = (cz * (bx * bx + bz * bz) - bz * (cx * cx + cz * cz)) / d, uz = (bx * (cx * cx + cz * cz) - cx * (bx * bx + bz * bz)) / d;
      return [a[0] + ux, a[1] + uz, Math.hypot(ux, uz)];
    };
    const inside = (c, p) => c && Math.hypot(p[0] - c[0], p[1] - c[1]) <= c[2] * (1 + 1e-9) + 1e-9;
    let c = null;
    for (let i = 0; i < points.length; i++) {
      if (inside(c, points[i])) continue;
      c = [points[i][0], points[i][1], 0];
      for (let j = 0; j < i; j++) {
        if (inside(c, points[j])) continue;
        c = circle2(points[i], points[j]);
        for (let k = 0; k < j; k++) {
          if (!inside(c, points[k])) c = circle3(points[i], points[j], points[k]) || c;
        }
      }
    }
    return c;
  }

  // ---- The match store: per cycle every fish pose and ball position, contacts, score, events.
  function Store(line0, item) {
    const layout = line0.layout;
    this.layout = layout;
    this.item = item || line0.item || 'default';
    this.nf = layout.fish.length;
    this.nb = layout.balls.length;
    this.nt = Math.max(2, layout.teams.length);
    this.stride = this.nf * STRIDE_FISH + this.nb * STRIDE_BALL;
    this.count = 0;
    this.firstCycle = line0.cycle | 0;
    this.frames = new Float32Array(Math.max(1, this.stride) * 64);
    this.contactStart = new Int32Array(65);
    this.contacts = new Float32Array(256);
    this.scores = new Float64Array(this.nt * 64);
    this.events = [];
    this.draws = []; // per cycle index: the strategies' debug drawings (run --debug-draw), if any
    this.hasDraws = false;
    this.logs = []; // what the strategies printed (run --strategy-log): {cycle, team, text}
    // What a body's details show: speeds and ball velocities, decisions and gears, and each contact's bodies.
    this.motionStride = this.nf * MOTION_FISH + this.nb * MOTION_BALL;
    this.motion = new Float32Array(Math.max(1, this.motionStride) * 64);
    this.codes = new Uint8Array(Math.max(1, this.nf * CODES_FISH) * 64);
    this.contactKinds = new Uint16Array(64);
    this.contactPairs = []; // [a, b, partA, partB]
    this.pairIndex = new Map();
    this.local = layout.fish.map(f => localLeaves(f.size));
  }
  Store.prototype.ensure = function (cycles, contactValues) {
    const grow = (arr, need, Type) => { if (arr.length >= need) return arr; const n = new Type(Math.max(need, arr.length * 2)); n.set(arr); return n; };
    this.frames = grow(this.frames, cycles * this.stride, Float32Array);
    this.contactStart = grow(this.contactStart, cycles + 1, Int32Array);
    this.contacts = grow(this.contacts, contactValues, Float32Array);
    this.scores = grow(this.scores, cycles * this.nt, Float64Array);
    this.motion = grow(this.motion, cycles * this.motionStride, Float32Array);
    this.codes = grow(this.codes, cycles * this.nf * CODES_FISH, Uint8Array);
    this.contactKinds = grow(this.contactKinds, contactValues / 4 + 1, Uint16Array);
  };
  // Appends one trace line (an object as in the trace file / the live stream).
  Store.prototype.append = function (line) {
    const k = this.count, cs = this.contactStart[k], contacts = line.contacts || [];
    this.ensure(k + 1, cs + contacts.length * 4);
    let o = k * this.stride;
    for (let i = 0; i < this.nf; i++) {
      const f = line.fish[i];
      this.frames[o++] = f.position[0]; this.frames[o++] = f.position[1]; this.frames[o++] = f.heading;
      this.frames[o++] = f.joints[0]; this.frames[o++] = f.joints[1]; this.frames[o++] = f.joints[2];
    }
    for (let i = 0; i < this.nb; i++) { const b = line.balls[i]; this.frames[o++] = b.position[0]; this.frames[o++] = b.position[1]; }
    let m = k * this.motionStride, d = k * this.nf * CODES_FISH;
    const code = v => (Number.isInteger(v) && v >= 0 && v < NO_CODE ? v : NO_CODE);
    for (let i = 0; i < this.nf; i++) {
      const f = line.fish[i], dec = f.decision || [], gears = f.gears || [];
      this.motion[m++] = +f.speed || 0; this.motion[m++] = +f.angularSpeed || 0;
      this.codes[d++] = code(dec[0]); this.codes[d++] = code(dec[1]); this.codes[d++] = code(gears[0]); this.codes[d++] = code(gears[1]);
    }
    for (let i = 0; i < this.nb; i++) { const v = line.balls[i].velocity || [0, 0]; this.motion[m++] = +v[0] || 0; this.motion[m++] = +v[1] || 0; }
    let c = cs;
    for (const ct of contacts) {
      const key = [ct.a, ct.b, ct.partA === undefined ? null : ct.partA, ct.partB === undefined ? null : ct.partB], name = JSON.stringify(key);
      let pair = this.pairIndex.get(name);
      if (pair === undefined) { pair = this.contactPairs.length; this.contactPairs.push(key); this.pairIndex.set(name, pair); }
      this.contactKinds[c / 4] = pair;
      this.contacts[c++] = ct.actionPoint[0]; this.contacts[c++] = ct.actionPoint[1]; this.contacts[c++] = ct.normal[0]; this.contacts[c++] = ct.normal[1];
    }
    this.contactStart[k + 1] = c;
    const score = line.score || [];
    for (let t = 0; t < this.nt; t++) this.scores[k * this.nt + t] = score[t] !== undefined ? score[t] : (k > 0 ? this.scores[(k - 1) * this.nt + t] : 0);
    for (const e of line.events || []) this.events.push(Object.assign({ cycle: line.cycle }, e));
    if (line.draw && line.draw.length > 0) { this.draws[k] = line.draw; this.hasDraws = true; }
    for (const l of line.log || []) this.logs.push({ cycle: line.cycle, team: l.team | 0, text: String(l.text) });
    this.count = k + 1;
  };
  // Builds a store from the page's packed replay (see Viewer/ReplayData.cs).
  Store.fromPacked = function (data) {
    const s = new Store({ layout: data.layout, item: data.item, cycle: data.firstCycle }, data.item);
    const n = data.cycles, q = data.q, a = data.angle;
    const frames = decode(data.frames, Int16Array), counts = decode(data.contactCounts, Uint16Array), packed = decode(data.contacts, Int16Array);
    s.ensure(n, packed.length);
    for (let k = 0, o = 0; k < n; k++) {
      for (let i = 0; i < s.nf; i++, o += STRIDE_FISH) {
        s.frames[o] = frames[o] * q; s.frames[o + 1] = frames[o + 1] * q;
        s.frames[o + 2] = frames[o + 2] * a; s.frames[o + 3] = frames[o + 3] * a; s.frames[o + 4] = frames[o + 4] * a; s.frames[o + 5] = frames[o + 5] * a;
      }
      for (let i = 0; i < s.nb; i++, o += STRIDE_BALL) { s.frames[o] = frames[o] * q; s.frames[o + 1] = frames[o + 1] * q; }
    }
    for (let k = 0, c = 0; k < n; k++) {
      s.contactStart[k] = c;
      for (let j = 0; j < counts[k]; j++, c += 4) {
        s.contacts[c] = packed[c] * q; s.contacts[c + 1] = packed[c + 1] * q; s.contacts[c + 2] = packed[c + 2] * a; s.contacts[c + 3] = packed[c + 3] * a;
      }
      s.contactStart[k + 1] = c;
    }
    if (data.motion !== undefined) {
      const motion = decode(data.motion, Int16Array), codes = decode(data.decisions, Uint8Array), kinds = decode(data.contactKinds, Uint16Array);
      for (let k = 0, o = 0; k < n; k++) {
        for (let i = 0; i < s.nf; i++, o += MOTION_FISH) { s.motion[o] = motion[o] * q; s.motion[o + 1] = motion[o + 1] * a; }
        for (let i = 0; i < s.nb; i++, o += MOTION_BALL) { s.motion[o] = motion[o] * q; s.motion[o + 1] = motion[o + 1] * q; }
      }
      s.codes.set(codes.subarray(0, Math.min(codes.length, s.codes.length)));
      s.contactKinds.set(kinds.subarray(0, Math.min(kinds.length, s.contactKinds.length)));
      s.contactPairs = data.contactPairs || [];
    } else s.codes.fill(NO_CODE);
    let change = 0;
    for (let k = 0; k < n; k++) {
      while (change < data.scores.length && data.scores[change][0] - s.firstCycle <= k) change++;
      const row = change > 0 ? data.scores[change - 1] : null;
      for (let t = 0; t < s.nt; t++) s.scores[k * s.nt + t] = row ? row[1 + t] : 0;
    }
    s.events = data.events;
    for (const [cycle, shapes] of data.draws || []) { s.draws[cycle - s.firstCycle] = shapes; s.hasDraws = true; }
    for (const [cycle, entries] of data.logs || []) for (const l of entries) s.logs.push({ cycle, team: l.team | 0, text: String(l.text) });
    s.count = n;
    return s;
  };
  function decode(text, Type) {
    const bin = atob(text), bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    return new Type(bytes.buffer, 0, bytes.length / Type.BYTES_PER_ELEMENT);
  }

  // ---- Page state and drawing.
  const $ = id => document.getElementById(id);
  const canvas = $('pool'), ctx = canvas.getContext('2d');
  const data = JSON.parse($('match-data').textContent);
  const api = {
    store: null, cycle: 0, position: 0, playing: false, speed: 1, follow: -1, live: !!data.live, followLive: !!data.live,
    show: { labels: true, contacts: false, bounds: false, trails: false, draw: [true, true, true, true] },
    inspected: null, // {kind: 'fish' | 'ball', index} whose details are shown
    tracked: [], // bodies whose trajectories are drawn: 'fish0', 'ball3', …
    trajectoryWindow: { from: null, to: null }, // cycle numbers; null: the first cycle / the cycle shown
    teamColour: t => TEAM_COLOURS[t % TEAM_COLOURS.length], ballColour: BALL_COLOUR,
    leaves, localLeaves, kdop, enclosingCircle, frames: 0, firstFrameAt: null, errors: [], received: 0,
    view: { scale: 1, cx: 0, cz: 0, ox: 0, oy: 0, dpr: 1 },
  };
  window.urwpg = api;

  function formatClock(cycle) {
    const total = Math.floor(cycle * CYCLE_SECONDS + 1e-9), m = Math.floor(total / 60), s = total % 60;
    return String(m).padStart(2, '0') + ':' + String(s).padStart(2, '0');
  }
  api.formatClock = formatClock;
  const formatNumber = v => (Math.round(v * 100) / 100).toString();

  function worldToCanvas(x, z) {
    const v = api.view;
    return [v.ox + (x - v.cx) * v.scale, v.oy + (z - v.cz) * v.scale];
  }
  api.worldToCanvas = worldToCanvas;

  // Pose of fish i / ball i at the (possibly fractional) display position.
  function fishPose(s, t, i) {
    const k = Math.floor(t), f = t - k, o = k * s.stride + i * STRIDE_FISH, fr = s.frames;
    if (f <= 0 || k + 1 >= s.count) return [fr[o], fr[o + 1], fr[o + 2], fr[o + 3], fr[o + 4], fr[o + 5]];
    const p = o + s.stride;
    if (Math.hypot(fr[p] - fr[o], fr[p + 1] - fr[o + 1]) > 300) return [fr[o], fr[o + 1], fr[o + 2], fr[o + 3], fr[o + 4], fr[o + 5]];
    let dh = fr[p + 2] - fr[o + 2];
    dh -= Math.round(dh / (2 * Math.PI)) * 2 * Math.PI;
    const lerp = j => fr[o + j] + (fr[p + j] - fr[o + j]) * f;
    return [lerp(0), lerp(1), fr[o + 2] + dh * f, lerp(3), lerp(4), lerp(5)];
  }
  function ballPos(s, t, i) {
    const k = Math.floor(t), f = t - k, base = s.nf * STRIDE_FISH + i * STRIDE_BALL, o = k * s.stride + base, fr = s.frames;
    if (f <= 0 || k + 1 >= s.count) return [fr[o], fr[o + 1]];
    const p = o + s.stride;
    if (Math.hypot(fr[p] - fr[o], fr[p + 1] - fr[o + 1]) > 300) return [fr[o], fr[o + 1]];
    return [fr[o] + (fr[p] - fr[o]) * f, fr[o + 1] + (fr[p + 1] - fr[o + 1]) * f];
  }
  api.fishPose = (k, i) => fishPose(api.store, k, i);
  api.ballPosition = (k, i) => ballPos(api.store, k, i);

  function resize() {
    const dpr = window.devicePixelRatio || 1, w = Math.max(1, Math.round(canvas.clientWidth * dpr)), h = Math.max(1, Math.round(canvas.clientHeight * dpr));
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    api.view.dpr = dpr;
    dirty = true;
  }

  function updateView(s, t) {
    const v = api.view, L = s.layout.field.length, W = s.layout.field.width;
    const fit = Math.min(canvas.width / (L + 2 * MARGIN_MM), canvas.height / (W + 2 * MARGIN_MM));
    v.ox = canvas.width / 2; v.oy = canvas.height / 2;
    if (api.follow >= 0 && api.follow < s.nf) {
      const p = fishPose(s, t, api.follow);
      v.scale = fit * FOLLOW_ZOOM; v.cx = p[0]; v.cz = p[1];
    } else {
      v.scale = fit; v.cx = 0; v.cz = 0;
    }
  }

  function path(points) {
    ctx.beginPath();
    points.forEach((p, i) => { const q = worldToCanvas(p[0], p[1]); if (i === 0) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]); });
    ctx.closePath();
  }
  function rect(min, max) { path([[min[0], min[1]], [max[0], min[1]], [max[0], max[1]], [min[0], max[1]]]); }
  function circle(x, z, r) { const q = worldToCanvas(x, z); ctx.beginPath(); ctx.arc(q[0], q[1], Math.max(0.5, r * api.view.scale), 0, 2 * Math.PI); }
  // A fish's number in its team, from 1, as the original numbered them (its Fishes[k - 1] in the
  // original API's code): fish of one team in the order of the layout.
  function teamNumber(layout, i) {
    let k = 0;
    for (let j = 0; j <= i; j++) if (layout.fish[j].team === layout.fish[i].team) k++;
    return k;
  }
  function fishLabel(layout, i) { return 'T' + layout.fish[i].team + '\u00b7' + teamNumber(layout, i); }
  function fishChoice(layout, i) { return 'fish' + i + ' (team ' + layout.fish[i].team + ' \u00b7 ' + teamNumber(layout, i) + ')'; }
  api.fishLabel = i => (api.store && i < api.store.nf ? fishLabel(api.store.layout, i) : null);
  function label(text, x, z, dx, dy, colour) {
    const q = worldToCanvas(x, z), px = Math.round(11 * api.view.dpr);
    ctx.font = '600 ' + px + 'px system-ui, sans-serif';
    ctx.textAlign = 'center'; ctx.textBaseline = 'middle';
    const w = ctx.measureText(text).width + 6 * api.view.dpr, h = px + 4 * api.view.dpr, lx = q[0] + dx * api.view.dpr, ly = q[1] + dy * api.view.dpr;
    ctx.fillStyle = 'rgba(255,255,255,0.85)'; ctx.fillRect(lx - w / 2, ly - h / 2, w, h);
    ctx.strokeStyle = colour; ctx.lineWidth = api.view.dpr; ctx.strokeRect(lx - w / 2, ly - h / 2, w, h);
    ctx.fillStyle = '#111'; ctx.fillText(text, lx, ly + 0.5);
  }

  function drawZone(z) {
    if (z.polygon) path(z.polygon);
    else if (z.min) rect(z.min, z.max);
    else if (z.center) circle(z.center[0], z.center[1], z.radius);
    else return;
    const colours = { hole: 'rgba(20,30,40,0.55)', target: 'rgba(80,200,120,0.35)', rescue: 'rgba(255,220,80,0.35)', forbidden: 'rgba(220,60,60,0.25)', 'goal-box': 'rgba(255,255,255,0.18)', start: 'rgba(180,180,255,0.25)' };
    ctx.fillStyle = z.team !== undefined ? hexAlpha(api.teamColour(z.team), 0.25) : (colours[z.kind] || 'rgba(255,255,255,0.2)');
    ctx.fill();
    ctx.setLineDash([6 * api.view.dpr, 4 * api.view.dpr]); ctx.strokeStyle = 'rgba(0,0,0,0.5)'; ctx.lineWidth = api.view.dpr; ctx.stroke(); ctx.setLineDash([]);
  }
  function hexAlpha(hex, a) { const n = parseInt(hex.slice(1), 16); return 'rgba(' + (n >> 16) + ',' + ((n >> 8) & 255) + ',' + (n & 255) + ',' + a + ')'; }

  function drawObstacle(o) {
    if (o.type === 'round') circle(o.center[0], o.center[1], o.radius);
    else {
      const c = Math.cos(o.heading), s = Math.sin(o.heading), a = o.length / 2, b = o.width / 2;
      path([[a, b], [-a, b], [-a, -b], [a, -b]].map(p => [o.center[0] + p[0] * c - p[1] * s, o.center[1] + p[0] * s + p[1] * c]));
    }
    ctx.fillStyle = '#6b5b4b'; ctx.fill(); ctx.strokeStyle = '#3b2f25'; ctx.lineWidth = api.view.dpr; ctx.stroke();
  }

  function draw() {
    const s = api.store;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#10212b'; ctx.fillRect(0, 0, canvas.width, canvas.height);
    if (!s || s.count === 0) return;
    const t = Math.min(api.position, s.count - 1), layout = s.layout, dpr = api.view.dpr;
    updateView(s, t);
    const L = layout.field.length / 2, W = layout.field.width / 2;
    // Pool, walls, goals, goal blocks, zones, obstacles.
    rect([-L, -W], [L, W]); ctx.fillStyle = '#cfe8f7'; ctx.fill();
    for (const g of layout.goals) { rect(g.min, g.max); ctx.fillStyle = hexAlpha(api.teamColour(g.team), 0.22); ctx.fill(); ctx.strokeStyle = api.teamColour(g.team); ctx.lineWidth = 2 * dpr; ctx.stroke(); }
    for (const b of layout.goalBlocks) { rect(b.min, b.max); ctx.fillStyle = '#8a8f94'; ctx.fill(); ctx.strokeStyle = '#4a4f54'; ctx.lineWidth = dpr; ctx.stroke(); }
    for (const z of layout.zones) drawZone(z);
    for (const o of layout.obstacles) drawObstacle(o);
    rect([-L, -W], [L, W]); ctx.strokeStyle = '#1b3a4b'; ctx.lineWidth = 3 * dpr; ctx.stroke();
    const k = Math.round(t) === t ? t : Math.floor(t);
    if (api.show.trails) drawTrails(s, k);
    if (api.tracked.length > 0) drawTrajectories(s, k);
    // Balls.
    for (let i = 0; i < s.nb; i++) {
      const p = ballPos(s, t, i);
      circle(p[0], p[1], layout.balls[i].radius); ctx.fillStyle = BALL_COLOUR; ctx.fill(); ctx.strokeStyle = '#8a4d08'; ctx.lineWidth = dpr; ctx.stroke();
    }
    // Fish: the eight leaves.
    const poses = [];
    for (let i = 0; i < s.nf; i++) {
      const p = fishPose(s, t, i), size = layout.fish[i].size, polys = leaves(size, p[0], p[1], p[2], p[3], p[4], p[5], s.local[i]);
      poses.push({ p, polys });
      ctx.fillStyle = api.teamColour(layout.fish[i].team); ctx.strokeStyle = i === api.follow ? '#ffffff' : '#1a1a1a'; ctx.lineWidth = (i === api.follow ? 2 : 1) * dpr;
      for (const poly of polys) { path(poly); ctx.fill(); ctx.stroke(); }
    }
    if (s.hasDraws) drawDebug(s, k);
    if (api.inspected) drawInspected(s, t);
    if (api.show.bounds) drawBounds(s, t, poses);
    if (api.show.contacts) drawContacts(s, k);
    if (api.show.labels) {
      for (let i = 0; i < s.nf; i++) {
        const { p } = poses[i], size = layout.fish[i].size, reach = size.length / 2 + size.head, c = Math.cos(p[2]), sn = Math.sin(p[2]);
        const tip = worldToCanvas(p[0] + reach * c, p[1] + reach * sn), end = worldToCanvas(p[0] + (reach + 70) * c, p[1] + (reach + 70) * sn);
        ctx.beginPath(); ctx.moveTo(tip[0], tip[1]); ctx.lineTo(end[0], end[1]); ctx.strokeStyle = '#111'; ctx.lineWidth = 1.5 * dpr; ctx.stroke();
        label(fishLabel(layout, i), p[0], p[1], 0, -26, api.teamColour(layout.fish[i].team));
      }
      for (let i = 0; i < s.nb; i++) {
        const p = ballPos(s, t, i), v = layout.balls[i].value;
        label(v !== undefined ? i + ' (' + formatNumber(v) + ')' : String(i), p[0], p[1] - layout.balls[i].radius, 0, -9, BALL_COLOUR);
      }
    }
    api.frames++;
    if (api.firstFrameAt === null) api.firstFrameAt = performance.now();
  }

  // The strategies' debug drawings of cycle index k, a layer per team (the team's checkbox).
  function drawDebug(s, k) {
    const shapes = s.draws[k], dpr = api.view.dpr;
    if (!shapes) return;
    for (const d of shapes) {
      const team = d.team | 0;
      if (!api.show.draw[team % 4]) continue;
      const colour = typeof d.color === 'string' && /^#[0-9a-f]{6}$/i.test(d.color) ? d.color : api.teamColour(team);
      ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = 2 * dpr;
      if (d.kind === 'line' && d.from && d.to) {
        const a = worldToCanvas(d.from[0], d.from[1]), b = worldToCanvas(d.to[0], d.to[1]);
        ctx.setLineDash([8 * dpr, 4 * dpr]); ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]); ctx.stroke(); ctx.setLineDash([]);
      } else if (d.kind === 'circle' && d.center) {
        circle(d.center[0], d.center[1], Math.max(0, +d.radius || 0)); ctx.stroke();
      } else if (d.kind === 'point' && d.at) {
        const q = worldToCanvas(d.at[0], d.at[1]); ctx.beginPath(); ctx.arc(q[0], q[1], 4 * dpr, 0, 2 * Math.PI); ctx.fill();
      } else if (d.kind === 'text' && d.at) {
        const q = worldToCanvas(d.at[0], d.at[1]), px = Math.round(12 * dpr);
        ctx.font = '600 ' + px + 'px system-ui, sans-serif'; ctx.textAlign = 'left'; ctx.textBaseline = 'alphabetic';
        ctx.lineWidth = 3 * dpr; ctx.strokeStyle = 'rgba(255,255,255,0.9)'; ctx.strokeText(String(d.text), q[0], q[1]); ctx.fillText(String(d.text), q[0], q[1]);
      }
    }
  }
  api.drawingsAt = k => (api.store && api.store.draws[k]) || [];

  // One checkbox per playing team for its drawings layer, shown once the match has drawings.
  function refreshDrawLayers(s) {
    const box = $('draw-layers');
    if (!s || !s.hasDraws) { box.hidden = true; return; }
    if (!box.hidden && box.dataset.teams === String(s.nt)) return;
    box.hidden = false; box.dataset.teams = String(s.nt);
    box.textContent = 'drawings';
    for (let t = 0; t < s.nt; t++) {
      if (!s.teamsPlaying[t]) continue;
      const label = document.createElement('label'), input = document.createElement('input');
      input.type = 'checkbox'; input.id = 'show-draw' + t; input.checked = api.show.draw[t];
      input.addEventListener('change', () => { api.show.draw[t] = input.checked; dirty = true; });
      label.appendChild(input); label.appendChild(document.createTextNode(' team ' + t));
      label.style.color = api.teamColour(t);
      box.appendChild(label);
    }
  }

  function drawTrails(s, k) {
    const from = Math.max(0, k - TRAIL_CYCLES), dpr = api.view.dpr;
    const trail = (get, colour) => {
      ctx.beginPath();
      let prev = null;
      for (let c = from; c <= k; c++) {
        const p = get(c), q = worldToCanvas(p[0], p[1]);
        if (!prev || Math.hypot(p[0] - prev[0], p[1] - prev[1]) > 300) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]);
        prev = p;
      }
      ctx.strokeStyle = colour; ctx.lineWidth = 2 * dpr; ctx.stroke();
    };
    for (let i = 0; i < s.nf; i++) trail(c => fishPose(s, c, i), hexAlpha(api.teamColour(s.layout.fish[i].team), 0.6));
    for (let i = 0; i < s.nb; i++) trail(c => ballPos(s, c, i), 'rgba(180,100,20,0.6)');
  }

  function drawBounds(s, t, poses) {
    const dpr = api.view.dpr;
    ctx.lineWidth = dpr;
    for (const { polys } of poses) {
      ctx.strokeStyle = 'rgba(0,120,0,0.8)';
      for (const poly of polys) { path(kdop(poly)); ctx.stroke(); }
      const all = [].concat(...polys), bodyGroup = [].concat(polys[0], polys[1], polys[2]), tailGroup = [].concat(...polys.slice(3));
      ctx.strokeStyle = 'rgba(120,0,160,0.8)';
      for (const pts of [all, bodyGroup, tailGroup]) { const c = enclosingCircle(pts); if (c) { circle(c[0], c[1], c[2]); ctx.stroke(); } }
    }
    ctx.strokeStyle = 'rgba(0,120,0,0.8)';
    for (let i = 0; i < s.nb; i++) { const p = ballPos(s, t, i), r = s.layout.balls[i].radius; rect([p[0] - r, p[1] - r], [p[0] + r, p[1] + r]); ctx.stroke(); }
  }

  function drawContacts(s, k) {
    const dpr = api.view.dpr;
    for (let c = s.contactStart[k]; c < s.contactStart[k + 1]; c += 4) {
      const x = s.contacts[c], z = s.contacts[c + 1], nx = s.contacts[c + 2], nz = s.contacts[c + 3];
      const a = worldToCanvas(x, z), b = worldToCanvas(x + nx * 80, z + nz * 80);
      ctx.beginPath(); ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]); ctx.strokeStyle = '#000'; ctx.lineWidth = 2 * dpr; ctx.stroke();
      const ang = Math.atan2(b[1] - a[1], b[0] - a[0]), h = 7 * dpr;
      ctx.beginPath(); ctx.moveTo(b[0], b[1]); ctx.lineTo(b[0] - h * Math.cos(ang - 0.4), b[1] - h * Math.sin(ang - 0.4)); ctx.lineTo(b[0] - h * Math.cos(ang + 0.4), b[1] - h * Math.sin(ang + 0.4)); ctx.closePath(); ctx.fillStyle = '#000'; ctx.fill();
      ctx.beginPath(); ctx.arc(a[0], a[1], 4 * dpr, 0, 2 * Math.PI); ctx.fillStyle = '#fff200'; ctx.fill(); ctx.strokeStyle = '#000'; ctx.lineWidth = dpr; ctx.stroke();
    }
  }

  // ---- One body's details (click it or choose it) and the trajectories of chosen bodies.
  const bodyId = b => b.kind + b.index;
  function parseBody(id) {
    const m = /^(fish|ball)(\d+)$/.exec(String(id));
    return m ? { kind: m[1], index: parseInt(m[2], 10) } : null;
  }
  function bodyCount(s, kind) { return kind === 'fish' ? s.nf : s.nb; }
  function bodyPosition(s, t, b) { return b.kind === 'fish' ? fishPose(s, t, b.index) : ballPos(s, t, b.index); }

  // The window of cycle indices a trajectory covers at cycle index k.
  function trajectoryRange(s, k) {
    const w = api.trajectoryWindow;
    const from = w.from === null ? 0 : Math.max(0, Math.min(s.count - 1, w.from - s.firstCycle));
    const to = w.to === null ? k : Math.max(0, Math.min(s.count - 1, w.to - s.firstCycle));
    return [Math.min(from, to), Math.max(from, to)];
  }
  // The polyline of a body over the window: [[x, z], ...] per cycle (a jump of over 300 mm starts a new piece).
  function trajectory(s, b, k) {
    const [from, to] = trajectoryRange(s, k), out = [];
    for (let c = from; c <= to; c++) { const p = bodyPosition(s, c, b); out.push([p[0], p[1]]); }
    return out;
  }
  api.trajectory = (id, k) => { const b = parseBody(id); return b && api.store ? trajectory(api.store, b, k === undefined ? api.cycle : k) : []; };

  function drawTrajectories(s, k) {
    const dpr = api.view.dpr;
    for (const id of api.tracked) {
      const b = parseBody(id);
      if (!b || b.index >= bodyCount(s, b.kind)) continue;
      const pts = trajectory(s, b, k), colour = b.kind === 'fish' ? api.teamColour(s.layout.fish[b.index].team) : '#b45f06';
      if (pts.length === 0) continue;
      ctx.beginPath();
      pts.forEach((p, i) => { const q = worldToCanvas(p[0], p[1]); if (i === 0 || Math.hypot(p[0] - pts[i - 1][0], p[1] - pts[i - 1][1]) > 300) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]); });
      ctx.strokeStyle = colour; ctx.lineWidth = 2.5 * dpr; ctx.stroke();
      for (const [p, r] of [[pts[0], 3], [pts[pts.length - 1], 5]]) {
        const q = worldToCanvas(p[0], p[1]); ctx.beginPath(); ctx.arc(q[0], q[1], r * dpr, 0, 2 * Math.PI); ctx.fillStyle = colour; ctx.fill(); ctx.strokeStyle = '#fff'; ctx.lineWidth = dpr; ctx.stroke();
      }
    }
  }

  function drawInspected(s, t) {
    const b = api.inspected;
    if (b.index >= bodyCount(s, b.kind)) return;
    const p = bodyPosition(s, t, b), r = b.kind === 'fish' ? s.layout.fish[b.index].size.length * 0.9 : s.layout.balls[b.index].radius + 25;
    circle(p[0], p[1], r);
    ctx.setLineDash([4 * api.view.dpr, 3 * api.view.dpr]); ctx.strokeStyle = '#ffffff'; ctx.lineWidth = 2 * api.view.dpr; ctx.stroke(); ctx.setLineDash([]);
  }

  // The body under a canvas point (CSS pixels), or null: a ball within 20 mm of its edge, else a fish whose leaves hold the point.
  function bodyAt(px, py) {
    const s = api.store;
    if (!s) return null;
    const v = api.view, x = (px * v.dpr - v.ox) / v.scale + v.cx, z = (py * v.dpr - v.oy) / v.scale + v.cz, t = Math.min(api.position, s.count - 1);
    let best = null, bestD = Infinity;
    for (let i = 0; i < s.nb; i++) {
      const p = ballPos(s, t, i), d = Math.hypot(p[0] - x, p[1] - z) - s.layout.balls[i].radius;
      if (d < 20 && d < bestD) { best = { kind: 'ball', index: i }; bestD = d; }
    }
    if (best) return best;
    for (let i = 0; i < s.nf; i++) {
      const p = fishPose(s, t, i), polys = leaves(s.layout.fish[i].size, p[0], p[1], p[2], p[3], p[4], p[5], s.local[i]);
      if (polys.some(poly => inside(poly, x, z))) return { kind: 'fish', index: i };
      const d = Math.hypot(p[0] - x, p[1] - z);
      if (d < s.layout.fish[i].size.length / 2 && d < bestD) { best = { kind: 'fish', index: i }; bestD = d; }
    }
    return best;
  }
  function inside(poly, x, z) {
    let c = false;
    for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
      const [xi, zi] = poly[i], [xj, zj] = poly[j];
      if ((zi > z) !== (zj > z) && x < (xj - xi) * (z - zi) / (zj - zi) + xi) c = !c;
    }
    return c;
  }
  api.bodyAt = bodyAt;

  function inspect(b) {
    api.inspected = b && api.store && b.index < bodyCount(api.store, b.kind) ? { kind: b.kind, index: b.index } : null;
    $('inspect').value = api.inspected ? bodyId(api.inspected) : '';
    // The trajectory box follows the choice at once (the rest of the panel with the next frame),
    // so that ticking it right after choosing tracks the body just chosen.
    $('track-body').disabled = !api.inspected;
    $('track-body').checked = !!api.inspected && api.tracked.includes(bodyId(api.inspected));
    hudDirty = true; dirty = true;
  }
  api.inspect = id => inspect(parseBody(id));

  // The details of the inspected body at cycle index k, as numbers (what the panel shows).
  function details(s, k) {
    const b = api.inspected;
    if (!b) return null;
    const n = cycleNumber(s, k), contacts = [];
    const me = bodyId(b);
    for (let c = s.contactStart[k]; c < s.contactStart[k + 1]; c += 4) {
      const pair = s.contactPairs[s.contactKinds[c / 4]];
      if (!pair) continue;
      if (pair[0] === me) contacts.push({ other: pair[1], part: pair[2], otherPart: pair[3], at: [s.contacts[c], s.contacts[c + 1]] });
      else if (pair[1] === me) contacts.push({ other: pair[0], part: pair[3], otherPart: pair[2], at: [s.contacts[c], s.contacts[c + 1]] });
    }
    const fr = s.frames, mo = s.motion;
    if (b.kind === 'fish') {
      const o = k * s.stride + b.index * STRIDE_FISH, m = k * s.motionStride + b.index * MOTION_FISH, d = (k * s.nf + b.index) * CODES_FISH;
      const team = s.layout.fish[b.index].team, codes = [0, 1, 2, 3].map(j => s.codes[d + j]);
      const faults = s.events.filter(e => e.kind === 'fault' && e.team === team && e.cycle <= n);
      return {
        id: me, cycle: n, team, position: [fr[o], fr[o + 1]], heading: fr[o + 2], joints: [fr[o + 3], fr[o + 4], fr[o + 5]],
        speed: mo[m], angularSpeed: mo[m + 1],
        decision: codes[0] === NO_CODE ? null : [codes[0], codes[1]], gears: codes[2] === NO_CODE ? null : [codes[2], codes[3]],
        contacts, faults: faults.map(e => ({ cycle: e.cycle, text: e.text || e.kind })),
      };
    }
    const o = k * s.stride + s.nf * STRIDE_FISH + b.index * STRIDE_BALL, m = k * s.motionStride + s.nf * MOTION_FISH + b.index * MOTION_BALL;
    const ball = s.layout.balls[b.index];
    return { id: me, cycle: n, position: [fr[o], fr[o + 1]], velocity: [mo[m], mo[m + 1]], speed: Math.hypot(mo[m], mo[m + 1]), radius: ball.radius, value: ball.value, contacts };
  }
  api.details = () => (api.store && api.inspected ? details(api.store, api.cycle) : null);

  const fixed = (v, d) => (Math.round(v * 10 ** d) / 10 ** d).toFixed(d);
  function renderDetails(s) {
    const box = $('details-body'), d = details(s, api.cycle);
    box.textContent = '';
    $('track-body').disabled = !d;
    $('track-body').checked = !!d && api.tracked.includes(d.id);
    if (!d) return;
    const rows = [['position', fixed(d.position[0], 1) + ', ' + fixed(d.position[1], 1) + ' mm']];
    if (d.team !== undefined) {
      rows.unshift(['team', 'team ' + d.team + ' (' + ((s.layout.teams[d.team] || {}).name || '') + ')']);
      rows.push(['heading', fixed(d.heading, 4) + ' rad (' + fixed(d.heading * 180 / Math.PI, 1) + '\u00b0)']);
      rows.push(['speed', fixed(d.speed, 1) + ' mm/s']);
      rows.push(['angular speed', fixed(d.angularSpeed, 4) + ' rad/s']);
      rows.push(['joints', d.joints.map(j => fixed(j, 4)).join(', ') + ' rad']);
      rows.push(['decision', d.decision ? 'VCode ' + d.decision[0] + ', TCode ' + d.decision[1] : '\u2014']);
      rows.push(['gears', d.gears ? 'speed ' + d.gears[0] + ', turn ' + d.gears[1] : '\u2014']);
    } else {
      rows.push(['velocity', fixed(d.velocity[0], 1) + ', ' + fixed(d.velocity[1], 1) + ' mm/s']);
      rows.push(['speed', fixed(d.speed, 1) + ' mm/s']);
      rows.push(['radius', fixed(d.radius, 1) + ' mm' + (d.value !== undefined ? ', value ' + formatNumber(d.value) : '')]);
    }
    rows.push(['contacts', d.contacts.length === 0 ? 'none' : d.contacts.map(c => (c.part ? c.part + ' \u2013 ' : '') + c.other + (c.otherPart ? ' ' + c.otherPart : '')).join('; ')]);
    if (d.faults) rows.push(['team faults', d.faults.length === 0 ? 'none' : d.faults.length + ', last #' + d.faults[d.faults.length - 1].cycle + ': ' + d.faults[d.faults.length - 1].text]);
    for (const [name, value] of rows) {
      const tr = document.createElement('tr'), th = document.createElement('th'), td = document.createElement('td');
      th.textContent = name; td.textContent = value; tr.dataset.name = name;
      tr.appendChild(th); tr.appendChild(td); box.appendChild(tr);
    }
  }

  function setupInspector(s) {
    const select = $('inspect');
    select.textContent = '';
    const none = document.createElement('option'); none.value = ''; none.textContent = 'click a fish or a ball'; select.appendChild(none);
    for (let i = 0; i < s.nf; i++) { const o = document.createElement('option'); o.value = 'fish' + i; o.textContent = fishChoice(s.layout, i); select.appendChild(o); }
    for (let i = 0; i < s.nb; i++) { const o = document.createElement('option'); o.value = 'ball' + i; o.textContent = 'ball' + i; select.appendChild(o); }
    if (api.inspected && api.inspected.index >= bodyCount(s, api.inspected.kind)) api.inspected = null;
    select.value = api.inspected ? bodyId(api.inspected) : '';
    const from = $('trajectory-from'), to = $('trajectory-to');
    from.min = to.min = String(s.firstCycle);
  }
  function setTrajectoryWindow(from, to) {
    const num = v => (v === null || v === undefined || v === '' || !isFinite(+v) ? null : Math.round(+v));
    api.trajectoryWindow = { from: num(from), to: num(to) };
    $('trajectory-from').value = api.trajectoryWindow.from === null ? '' : String(api.trajectoryWindow.from);
    $('trajectory-to').value = api.trajectoryWindow.to === null ? '' : String(api.trajectoryWindow.to);
    dirty = true;
  }
  api.setTrajectoryWindow = setTrajectoryWindow;
  function track(id, on) {
    api.tracked = api.tracked.filter(x => x !== id);
    if (on) api.tracked.push(id);
    hudDirty = true; dirty = true;
  }
  api.track = track;

  // ---- The heads-up display (score, clock, events) and the controls.
  let dirty = true, lastEventsShown = -1, lastCycleShown = -1;
  function cycleNumber(s, k) { return s.firstCycle + k; }

  function updateHud() {
    const s = api.store;
    if (!s) return;
    const k = api.cycle;
    if (k === lastCycleShown && s.events.length === lastEventsShown && !hudDirty) return;
    hudDirty = false;
    const previous = lastCycleShown;
    lastCycleShown = k;
    const n = cycleNumber(s, k);
    $('clock').textContent = formatClock(n);
    // The total: the match's last cycle; live while it is played, its length from the server (its
    // regular time, or the cycle reached in an item's extra time), not the last cycle received.
    const last = cycleNumber(s, Math.max(0, s.count - 1));
    const st = api.serverStatus;
    const total = api.live && st && !st.over ? Math.max(st.cycles, last) : last;
    $('cycle').textContent = 'cycle ' + n + ' / ' + total;
    const row = k * s.nt;
    // The scores of the teams that play, in team order (a one-team item shows its team's alone).
    const shown = [];
    for (let t = 0; t < s.nt; t++) if (s.teamsPlaying[t]) shown.push(formatNumber(s.scores[row + t]));
    $('score').textContent = shown.join(' : ');
    const scrub = $('scrub');
    scrub.max = String(Math.max(0, s.count - 1));
    if (document.activeElement !== scrub || String(k) !== scrub.value) scrub.value = String(k);
    if (s.events.length !== lastEventsShown || previous !== k) renderEvents(s, n, previous);
    if (s.logs.length !== lastLogsShown || previous !== k || logFilterChanged) renderLogs(s, n);
    refreshDrawLayers(s);
    renderDetails(s);
    lastEventsShown = s.events.length;
  }
  let hudDirty = true;

  function renderEvents(s, n, previous) {
    const list = $('events');
    list.textContent = '';
    let latest = null;
    for (let i = s.events.length - 1; i >= 0; i--) {
      const e = s.events[i];
      if (e.cycle > n) continue;
      const li = document.createElement('li');
      li.dataset.cycle = e.cycle;
      const at = document.createElement('span'); at.className = 'at'; at.textContent = formatClock(e.cycle) + ' #' + e.cycle;
      li.appendChild(at); li.appendChild(document.createTextNode(e.text || e.kind));
      if (e.cycle === n) li.className = 'now';
      list.appendChild(li);
      if (latest === null) latest = e;
      if (list.childElementCount >= 200) break;
    }
    // A toast for events reached by playing or stepping forward (not by jumps of the scrub bar).
    if (previous >= 0 && n > cycleNumber(s, previous) && (api.playing || api.followLive || n - cycleNumber(s, previous) <= 10)) {
      const passed = s.events.filter(e => e.cycle > cycleNumber(s, previous) && e.cycle <= n);
      if (passed.length > 0) toast(passed.map(e => e.text || e.kind).join(' · '));
    }
  }
  // What the strategies printed up to the cycle shown, newest first, for the team chosen (or all).
  let lastLogsShown = -1, logFilterChanged = false;
  function renderLogs(s, n) {
    lastLogsShown = s.logs.length; logFilterChanged = false;
    const box = $('strategy-output');
    box.hidden = s.logs.length === 0;
    if (box.hidden) return;
    const filter = $('log-team'), team = filter.value === 'all' ? -1 : parseInt(filter.value, 10);
    if (filter.options.length !== s.nt + 1) {
      filter.textContent = '';
      const all = document.createElement('option'); all.value = 'all'; all.textContent = 'every team'; filter.appendChild(all);
      for (let t = 0; t < s.nt; t++) { const o = document.createElement('option'); o.value = String(t); o.textContent = 'team ' + t; filter.appendChild(o); }
      filter.value = team < 0 ? 'all' : String(team);
    }
    const list = $('strategy-log');
    list.textContent = '';
    for (let i = s.logs.length - 1; i >= 0 && list.childElementCount < 200; i--) {
      const l = s.logs[i];
      if (l.cycle > n || (team >= 0 && l.team !== team)) continue;
      const li = document.createElement('li');
      li.dataset.cycle = l.cycle; li.dataset.team = l.team;
      const at = document.createElement('span'); at.className = 'at'; at.textContent = '#' + l.cycle + ' team ' + l.team;
      at.style.color = api.teamColour(l.team);
      const text = document.createElement('pre'); text.textContent = l.text;
      li.appendChild(at); li.appendChild(text);
      if (l.cycle === n) li.className = 'now';
      list.appendChild(li);
    }
  }
  api.logsShown = () => Array.from(document.querySelectorAll('#strategy-log li')).map(li => ({ cycle: +li.dataset.cycle, team: +li.dataset.team, text: li.querySelector('pre').textContent }));

  let toastTimer = 0;
  function toast(text) {
    const el = $('toast');
    el.textContent = text; el.className = 'on';
    clearTimeout(toastTimer);
    toastTimer = setTimeout(() => { el.className = ''; }, 2500);
  }

  function setTeams(s) {
    // The teams that play: those with fish (teams 0 and 1 when the match has none). The trace lists
    // at least two teams and scores (four for four-teams); a one-team item's other team has no fish
    // and is not shown.
    s.teamsPlaying = [];
    for (let t = 0; t < s.nt; t++) s.teamsPlaying.push(s.layout.fish.length === 0 ? t < 2 : s.layout.fish.some(f => f.team === t));
    for (let t = 0; t < 4; t++) {
      const team = s.layout.teams[t] || { name: 'team ' + t }, el = $('team' + t);
      if (t >= s.nt) { el.style.display = 'none'; continue; }
      el.querySelector('.swatch').style.background = api.teamColour(t);
      el.querySelector('.name').textContent = 'team ' + t + ' (' + team.name + ')';
      el.style.display = s.teamsPlaying[t] ? '' : 'none';
    }
    $('item').textContent = s.item === 'default' ? '' : s.item;
    const follow = $('follow');
    while (follow.options.length > 1) follow.remove(1);
    s.layout.fish.forEach((f, i) => { const o = document.createElement('option'); o.value = String(i); o.textContent = fishChoice(s.layout, i); follow.appendChild(o); });
    follow.value = String(api.follow < s.nf ? api.follow : -1);
    setupInspector(s);
    hudDirty = true;
  }

  // Moves the display to cycle index k (0 = the first line), stopping playback.
  function seek(k) {
    const s = api.store;
    if (!s) return;
    api.playing = false;
    api.cycle = Math.max(0, Math.min(s.count - 1, Math.round(k)));
    api.position = api.cycle;
    if (api.live) api.followLive = api.cycle === s.count - 1 && api.followLive;
    updatePlayButton();
    dirty = true;
  }
  api.seek = seek;
  function step(d) { if (api.live) api.followLive = false; seek(api.cycle + d); }
  api.step = step;
  function nextEvent() {
    const s = api.store;
    if (!s) return;
    const n = cycleNumber(s, api.cycle), e = s.events.find(ev => ev.cycle > n);
    if (e) { if (api.live) api.followLive = false; seek(e.cycle - s.firstCycle); }
  }
  api.nextEvent = nextEvent;
  function play(on) {
    const s = api.store;
    if (!s) return;
    api.playing = on;
    if (on && api.cycle >= s.count - 1 && !api.live) { api.cycle = 0; api.position = 0; }
    if (on && api.live) api.followLive = false;
    updatePlayButton();
    dirty = true;
  }
  api.play = play;
  function setSpeed(x) {
    api.speed = x;
    $('speed').value = String(x);
  }
  api.setSpeed = setSpeed;
  function updatePlayButton() {
    $('play').innerHTML = api.playing ? '&#10074;&#10074;' : '&#9654;';
    const lf = $('live-follow');
    if (lf) lf.classList.toggle('on', api.followLive);
  }

  function setup() {
    const speed = $('speed');
    for (const x of SPEEDS) { const o = document.createElement('option'); o.value = String(x); o.textContent = x + '\u00d7'; speed.appendChild(o); }
    speed.value = '1';
    speed.addEventListener('change', () => setSpeed(parseFloat(speed.value)));
    $('play').addEventListener('click', () => play(!api.playing));
    $('back').addEventListener('click', () => step(-1));
    $('fwd').addEventListener('click', () => step(1));
    $('next').addEventListener('click', nextEvent);
    const scrub = $('scrub');
    scrub.addEventListener('input', () => { if (api.live) api.followLive = false; seek(parseInt(scrub.value, 10)); });
    $('follow').addEventListener('change', e => { api.follow = parseInt(e.target.value, 10); dirty = true; });
    for (const name of ['labels', 'contacts', 'bounds', 'trails']) {
      const box = $('show-' + name);
      box.checked = api.show[name];
      box.addEventListener('change', () => { api.show[name] = box.checked; dirty = true; });
    }
    $('log-team').addEventListener('change', () => { logFilterChanged = true; hudDirty = true; dirty = true; });
    $('inspect').addEventListener('change', e => inspect(parseBody(e.target.value)));
    canvas.addEventListener('click', e => { const b = bodyAt(e.offsetX, e.offsetY); if (b) inspect(b); });
    $('track-body').addEventListener('change', e => { if (api.inspected) track(bodyId(api.inspected), e.target.checked); });
    for (const id of ['trajectory-from', 'trajectory-to']) $(id).addEventListener('change', () => setTrajectoryWindow($('trajectory-from').value, $('trajectory-to').value));
    $('strategy-log').addEventListener('click', e => {
      const li = e.target.closest('li');
      if (li && api.store) { if (api.live) api.followLive = false; seek(parseInt(li.dataset.cycle, 10) - api.store.firstCycle); }
    });
    $('events').addEventListener('click', e => {
      const li = e.target.closest('li');
      if (li && api.store) { if (api.live) api.followLive = false; seek(parseInt(li.dataset.cycle, 10) - api.store.firstCycle); }
    });
    document.addEventListener('keydown', e => {
      if (e.target instanceof HTMLInputElement && e.target.type !== 'range' && e.target.type !== 'checkbox') return;
      if (e.target instanceof HTMLSelectElement) return;
      const i = SPEEDS.indexOf(api.speed);
      switch (e.key) {
        case ' ': play(!api.playing); break;
        case 'ArrowRight': step(e.shiftKey ? 10 : 1); break;
        case 'ArrowLeft': step(e.shiftKey ? -10 : -1); break;
        case '+': case '=': case 'ArrowUp': setSpeed(SPEEDS[Math.min(SPEEDS.length - 1, i + 1)]); break;
        case '-': case '_': case 'ArrowDown': setSpeed(SPEEDS[Math.max(0, i - 1)]); break;
        case 'n': nextEvent(); break;
        case 'Home': seek(0); break;
        case 'End': seek(api.store ? api.store.count - 1 : 0); break;
        default: return;
      }
      e.preventDefault();
    });
    window.addEventListener('resize', resize);
    if (window.ResizeObserver) new ResizeObserver(resize).observe(canvas);
    resize();
  }

  let lastTime = null;
  function frame(now) {
    const s = api.store;
    if (s && lastTime !== null && api.playing) {
      const dt = Math.min(0.25, (now - lastTime) / 1000);
      api.position = Math.min(s.count - 1, api.position + dt * api.speed / CYCLE_SECONDS);
      api.cycle = Math.floor(api.position);
      if (api.position >= s.count - 1) {
        api.playing = false; api.position = api.cycle = s.count - 1;
        if (api.live) api.followLive = true;
        updatePlayButton();
      }
      dirty = true;
    }
    if (s && api.live && api.followLive && api.cycle !== s.count - 1) { api.cycle = s.count - 1; api.position = api.cycle; dirty = true; }
    lastTime = now;
    if (dirty) { draw(); updateHud(); dirty = false; }
    requestAnimationFrame(frame);
  }

  // ---- Live: the server streams trace lines; controls post to /control.
  function connectLive() {
    $('live-controls').hidden = false;
    $('live-status').hidden = false;
    const status = $('live-status');
    const source = new EventSource('events');
    api.source = source;
    source.addEventListener('reset', () => { api.store = null; api.cycle = 0; api.position = 0; lastCycleShown = -1; lastEventsShown = -1; lastLogsShown = -1; dirty = true; });
    source.addEventListener('status', e => {
      const st = JSON.parse(e.data);
      api.serverStatus = st;
      hudDirty = true;
      status.textContent = (st.over ? 'match over' : st.paused ? 'match paused' : 'live \u00b7 ' + st.speed + '\u00d7') + (api.viewOnly ? ' \u00b7 view only' : '');
      $('server-pause').textContent = st.paused ? 'resume match' : 'pause match';
    });
    source.onmessage = e => {
      const line = JSON.parse(e.data);
      if (line.layout) { api.store = new Store(line); setTeams(api.store); }
      if (!api.store) return;
      api.store.append(line);
      api.received++;
      hudDirty = true;
      dirty = true;
    };
    source.onerror = () => { status.textContent = 'disconnected (reconnecting)'; };
    // A server others can reach lets only the holder of its control token (the page's ?token=) steer.
    const token = new URLSearchParams(location.search).get('token');
    api.withToken = params => { if (token) params.set('token', token); return params; };
    const post = action => fetch('control?' + api.withToken(new URLSearchParams({ action })).toString(), { method: 'POST' });
    api.viewOnly = false;
    fetch('access?' + api.withToken(new URLSearchParams()).toString()).then(r => r.json()).then(a => {
      api.viewOnly = !a.control;
      for (const id of ['server-pause', 'server-step', 'server-restart', 'board-start', 'board-recompile']) $(id).hidden = api.viewOnly;
      if (api.viewOnly) status.textContent += ' \u00b7 view only';
    });
    $('server-pause').addEventListener('click', () => post(api.serverStatus && api.serverStatus.paused ? 'resume' : 'pause'));
    $('server-step').addEventListener('click', () => post('step'));
    $('server-restart').addEventListener('click', () => post('restart'));
    $('live-follow').addEventListener('click', () => { api.followLive = true; api.playing = false; updatePlayButton(); dirty = true; });
    api.control = post;
  }

  // ---- Control board (run --live --strategies DIR): GET board lists the choices; start and
  // recompile post them to /control. Every answer (lines; refused: why) is shown under the buttons.
  function connectBoard() {
    $('board').hidden = false;
    const item = $('board-item'), length = $('board-length'), cycles = $('board-cycles'), teams = $('board-teams'), message = $('board-message');
    const buttons = [$('board-start'), $('board-recompile'), $('board-refresh')];
    api.boardReplies = 0;
    const option = (select, value, text) => { const o = document.createElement('option'); o.value = value; o.textContent = text; select.appendChild(o); return o; };
    const show = (text, bad) => { message.textContent = text; message.classList.toggle('bad', !!bad); api.boardMessage = { text, bad: !!bad }; };
    function teamSelects(keep) {
      const b = api.board, chosen = b.items.find(i => i.id === item.value) || b.items[0];
      teams.textContent = '';
      for (let t = 0; t < chosen.teams; t++) {
        const label = document.createElement('label'), select = document.createElement('select');
        label.append('team ' + t + ' ');
        select.id = 'board-team' + t;
        select.setAttribute('aria-label', 'team ' + t);
        for (const name of b.builtIns) if (name !== 'demo' || chosen.demo) option(select, name, name === 'scene' ? (chosen.demo ? 'scene (demo)' : 'scene') : name);
        for (const name of b.strategies) option(select, name, name);
        const cli = b.commandLine[t];
        if (cli && !b.builtIns.includes(cli) && !b.strategies.includes(cli)) option(select, cli, cli + ' (command line)');
        const want = keep && keep[t] !== undefined ? keep[t] : 'scene';
        select.value = Array.from(select.options).some(o => o.value === want) ? want : 'scene';
        label.appendChild(select);
        teams.appendChild(label);
      }
    }
    function lengths() {
      const b = api.board, chosen = b.items.find(i => i.id === item.value) || b.items[0], keep = length.value;
      length.textContent = '';
      option(length, '', 'default (' + chosen.cycles + ' cycles)');
      for (const m of b.minutes) option(length, 'm' + m, m + ' min');
      option(length, 'cycles', 'cycles\u2026');
      length.value = Array.from(length.options).some(o => o.value === keep) ? keep : '';
      cycles.hidden = length.value !== 'cycles';
    }
    function fill(b, first) {
      const keepItem = first ? b.current.item : item.value;
      const keepTeams = first ? b.current.teams : Array.from(teams.querySelectorAll('select')).map(s => s.value);
      api.board = b;
      item.textContent = '';
      for (const i of b.items) option(item, i.id, i.name);
      item.value = keepItem;
      if (first && b.current.cycles !== null) cycles.value = b.current.cycles;
      lengths();
      if (first) length.value = b.current.minutes !== null ? 'm' + b.current.minutes : b.current.cycles !== null ? 'cycles' : '';
      cycles.hidden = length.value !== 'cycles';
      teamSelects(keepTeams);
    }
    const refresh = first => fetch('board').then(r => r.json()).then(b => { fill(b, first); api.boardLoads = (api.boardLoads || 0) + 1; });
    async function send(action, params) {
      buttons.forEach(b => { b.disabled = true; });
      show(action === 'start' ? 'starting\u2026' : 'recompiling\u2026', false);
      try {
        const r = await fetch('control?' + api.withToken(params).toString(), { method: 'POST' });
        const text = await r.text();
        show(r.ok ? text + (action === 'start' ? 'started' : 'recompiled and restarted') : text, !r.ok);
      } catch (e) {
        show('no answer from the server (' + e.message + ')', true);
      }
      buttons.forEach(b => { b.disabled = false; });
      api.boardReplies++;
    }
    item.addEventListener('change', () => { lengths(); teamSelects(Array.from(teams.querySelectorAll('select')).map(s => s.value)); });
    length.addEventListener('change', () => { cycles.hidden = length.value !== 'cycles'; });
    $('board-start').addEventListener('click', () => {
      const p = new URLSearchParams({ action: 'start', item: item.value });
      if (length.value === 'cycles') p.set('cycles', cycles.value);
      else if (length.value) p.set('minutes', length.value.slice(1));
      teams.querySelectorAll('select').forEach((s, t) => p.set('team' + t, s.value));
      send('start', p);
    });
    $('board-recompile').addEventListener('click', () => send('recompile', new URLSearchParams({ action: 'recompile' })));
    $('board-refresh').addEventListener('click', () => refresh(false));
    $('board-save-png').addEventListener('click', () => {
      const a = document.createElement('a'), s = api.store;
      a.href = canvas.toDataURL('image/png');
      a.download = 'field-cycle' + (s ? s.firstCycle + api.cycle : 0) + '.png';
      document.body.appendChild(a);
      a.click();
      a.remove();
    });
    refresh(true);
  }

  window.addEventListener('error', e => api.errors.push(String(e.message)));
  setup();
  if (data.live) { connectLive(); if (data.board) connectBoard(); }
  else {
    api.store = Store.fromPacked(data); setTeams(api.store);
    // A link to a moment of the match (a tournament report's first fault): page.html#cycle=N opens at cycle N.
    const at = /^#cycle=(\d+)$/.exec(location.hash);
    if (at) seek(parseInt(at[1], 10) - api.store.firstCycle);
  }
  updatePlayButton();
  requestAnimationFrame(frame);
})();
