// page.js -- rollviz's web page viewer (render/export/WebPage.cpp writes the data it reads).
//
// The data (the JSON in #rollviz-data; arrays are base64 of little-endian typed arrays):
//   frames, fps, speed, t (f64 per frame), x (f64, frames x variables), energyError (f64 per frame, NaN: none),
//   title, description, parameters [[name, value]], variables [names],
//   camera {angle (vertical, degrees), frames (f32: position, focal point, view up per frame)},
//   background [r, g, b], background2 (the top of a gradient, or absent),
//   textures [PNG data URIs], geometries [{positions f32, normals f32, uvs f32, colours u8 RGBA,
//   triangles / segments / points u32, strip, dots, like (all but the positions are that geometry's)}],
//   actors [{name, material {colour, opacity, specular, shininess, lit, wireframe, lineWidth, pointSize,
//   texture, repeat}, versions [{from, geometry, counts u32, ends f32}], matrices (f32, 16 per frame or one,
//   column-major), visible (u8 per frame or one)}],
//   map (a session's Poincare map) {x, y, series [{kind points|curve|markers, colour, x f64, y f64}]}.
// A growing version (a trace) shows the first counts[k] vertices of its geometry at frame k, the last of
// them moved to ends[k].
//
// Drawing is three.js's WebGLRenderer; where WebGL is not available (a browser without a GPU driver) the same
// scene is drawn by a small painter's-algorithm renderer into a 2D canvas (flat shading), so the page still
// plays and turns. window.rollviz is the page's interface for scripts and tests.
(function () {
  'use strict';
  const D = JSON.parse(document.getElementById('rollviz-data').textContent);

  function bytes(b64) {
    const s = atob(b64);
    const a = new Uint8Array(s.length);
    for (let i = 0; i < s.length; ++i) a[i] = s.charCodeAt(i);
    return a;
  }
  const typed = (Type) => (b64) => (b64 == null ? null : new Type(bytes(b64).buffer));
  const f32 = typed(Float32Array), f64 = typed(Float64Array), u32 = typed(Uint32Array);
  const u8 = (b64) => (b64 == null ? null : bytes(b64));

  const frames = D.frames;
  const times = f64(D.t), states = f64(D.x), energy = f64(D.energyError), cams = f32(D.camera.frames);
  const dim = D.variables.length;

  // --- the page's text
  document.getElementById('title').textContent = D.title || 'rollviz';
  document.getElementById('description').textContent = D.description || '';
  const table = document.getElementById('parameters');
  for (const [name, value] of D.parameters) {
    const row = table.insertRow();
    row.insertCell().textContent = name;
    row.insertCell().textContent = value;
  }
  if (!D.parameters.length) document.getElementById('parameters-box').classList.add('hidden');

  // --- the 3D view
  const view = document.getElementById('view');
  const bg = D.background, bg2 = D.background2;
  const css = (c) => `rgb(${c.map((v) => Math.round(255 * v)).join(',')})`;
  view.style.background = bg2 ? `linear-gradient(${css(bg2)}, ${css(bg)})` : css(bg);

  function webglAvailable() {
    try {
      const c = document.createElement('canvas');
      return !!(window.WebGLRenderingContext && (c.getContext('webgl') || c.getContext('experimental-webgl')));
    } catch (e) {
      return false;
    }
  }
  const webgl = webglAvailable();
  let renderer;
  if (webgl) {
    renderer = new THREE.WebGLRenderer({ antialias: true, alpha: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setClearColor(0x000000, 0);
  } else {
    renderer = new CanvasFallback();
  }
  view.insertBefore(renderer.domElement, view.firstChild);

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(D.camera.angle, 1, 1e-3, 1e4);
  camera.up.set(cams[6], cams[7], cams[8]); // OrbitControls keeps the up it finds
  const light = new THREE.DirectionalLight(0xffffff, 0.85); // VTK's headlight
  light.position.set(0, 0, 1);
  camera.add(light);
  light.target.position.set(0, 0, -1);
  camera.add(light.target);
  scene.add(camera);
  scene.add(new THREE.AmbientLight(0xffffff, 0.22));

  const textures = D.textures.map((uri) => {
    const image = new Image();
    const t = new THREE.Texture(image);
    image.onload = () => {
      t.needsUpdate = true;
      renderer.textureLoaded && renderer.textureLoaded(t);
      dirty = true;
    };
    image.src = uri;
    return t;
  });

  function material(m, kind, colours) {
    const colour = new THREE.Color(m.colour[0], m.colour[1], m.colour[2]);
    const common = {
      color: colour,
      transparent: m.opacity < 1,
      opacity: m.opacity,
      vertexColors: colours ? THREE.VertexColors : THREE.NoColors,
    };
    if (kind === 'lines') return new THREE.LineBasicMaterial(Object.assign(common, { linewidth: m.lineWidth }));
    if (kind === 'points')
      return new THREE.PointsMaterial(Object.assign(common, { size: Math.max(2, m.pointSize * 2), sizeAttenuation: false }));
    let map = null;
    if (m.texture !== undefined) {
      map = textures[m.texture];
      if (m.repeat) map.wrapS = map.wrapT = THREE.RepeatWrapping;
    }
    const surface = Object.assign(common, { side: THREE.DoubleSide, map: map, wireframe: m.wireframe });
    if (!m.lit) return new THREE.MeshBasicMaterial(surface);
    const s = m.specular;
    return new THREE.MeshPhongMaterial(
      Object.assign(surface, { specular: new THREE.Color(s, s, s), shininess: m.shininess }));
  }

  // One actor's version: a group of a mesh, segments and points over shared vertices, or a growing line.
  function build(g, m, growing) {
    if (g.like !== undefined) g = Object.assign({}, D.geometries[g.like], { positions: g.positions });
    const positions = f32(g.positions).slice(); // a growing line's end is moved in place
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    if (g.normals) geometry.setAttribute('normal', new THREE.BufferAttribute(f32(g.normals), 3));
    if (g.uvs) geometry.setAttribute('uv', new THREE.BufferAttribute(f32(g.uvs), 2));
    const colours = u8(g.colours);
    if (colours) geometry.setAttribute('color', new THREE.BufferAttribute(colours, 4, true));
    const group = new THREE.Group();
    group.matrixAutoUpdate = false;
    const part = (index, Kind, kind) => {
      const geo = index ? geometry.clone() : geometry;
      if (index) geo.setIndex(new THREE.BufferAttribute(index, 1));
      if (Kind === THREE.Mesh && !g.normals) geo.computeVertexNormals();
      const o = new Kind(geo, material(m, kind, colours));
      o.frustumCulled = false;
      o.matrixAutoUpdate = false;
      group.add(o);
      return o;
    };
    if (g.strip || g.dots) {
      group.userData.line = part(null, g.dots ? THREE.Points : THREE.Line, g.dots ? 'points' : 'lines');
      group.userData.original = f32(g.positions);
    } else {
      if (g.triangles) part(u32(g.triangles), THREE.Mesh, 'surface');
      if (g.segments) part(u32(g.segments), THREE.LineSegments, 'lines');
      if (g.points) part(u32(g.points), THREE.Points, 'points');
    }
    if (growing) {
      group.userData.counts = u32(growing.counts);
      group.userData.ends = f32(growing.ends);
    }
    return group;
  }

  const geometries = D.geometries;
  const actors = D.actors.map((a) => {
    const versions = a.versions.map((v) => {
      const object = build(geometries[v.geometry], a.material, v.counts ? v : null);
      object.visible = false;
      scene.add(object);
      return { from: v.from, object: object };
    });
    return { name: a.name, versions: versions, matrices: f32(a.matrices), visible: u8(a.visible) };
  });

  // --- the camera: the scene's at every frame until the user turns it; then the user's, carried along with
  // what the scene's camera looks at (as the body rolls away)
  const controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.enableDamping = false;
  controls.enableKeys = false;
  let userCamera = false;
  controls.addEventListener('start', () => { userCamera = true; });
  controls.addEventListener('change', () => { dirty = true; });

  function focal(k) {
    return new THREE.Vector3(cams[9 * k + 3], cams[9 * k + 4], cams[9 * k + 5]);
  }
  function sceneCamera(k) {
    camera.position.set(cams[9 * k], cams[9 * k + 1], cams[9 * k + 2]);
    camera.up.set(cams[9 * k + 6], cams[9 * k + 7], cams[9 * k + 8]);
    controls.target.copy(focal(k));
    camera.lookAt(controls.target);
    const distance = camera.position.distanceTo(controls.target);
    camera.near = distance / 1000;
    camera.far = distance * 1000;
    camera.updateProjectionMatrix();
  }

  // --- frames
  let frame = -1, dirty = true;
  function setFrame(k) {
    k = Math.max(0, Math.min(frames - 1, k | 0));
    if (k === frame) return;
    const previous = frame;
    frame = k;
    for (const a of actors) {
      let current = null;
      for (const v of a.versions) if (v.from <= k) current = v;
      const shown = a.visible.length === 1 ? a.visible[0] : a.visible[k];
      const offset = a.matrices.length === 16 ? 0 : 16 * k;
      for (const v of a.versions) v.object.visible = v === current && !!shown;
      if (!current) continue;
      const o = current.object;
      o.matrix.fromArray(a.matrices, offset);
      o.matrixWorldNeedsUpdate = true;
      const u = o.userData;
      if (u.counts) {
        const i = k - current.from, n = u.counts[i];
        const positions = u.line.geometry.attributes.position;
        if (u.moved !== undefined) positions.array.set(u.original.subarray(3 * u.moved, 3 * u.moved + 3), 3 * u.moved);
        if (n > 0) {
          positions.array.set(u.ends.subarray(3 * i, 3 * i + 3), 3 * (n - 1));
          u.moved = n - 1;
        }
        positions.needsUpdate = true;
        u.line.geometry.setDrawRange(0, n);
      }
    }
    if (!userCamera) sceneCamera(k);
    else if (previous >= 0) {
      const shift = focal(k).sub(focal(previous));
      camera.position.add(shift);
      controls.target.add(shift);
    }
    const slider = document.getElementById('slider');
    slider.value = k;
    const e = energy[k];
    document.getElementById('time').textContent = `t = ${times[k].toFixed(3)}`;
    document.getElementById('hud').textContent =
      `t = ${times[k].toFixed(2)}` + (Number.isFinite(e) ? `   dE/E = ${e.toExponential(1)}` : '');
    dirty = true;
  }

  // --- playing
  let playing = true, speed = 1, position = 0, last = null;
  const play = document.getElementById('play');
  function setPlaying(on) {
    playing = on;
    play.textContent = on ? 'Pause' : 'Play';
    last = null;
  }
  play.addEventListener('click', () => setPlaying(!playing));
  document.addEventListener('keydown', (e) => {
    if (e.code === 'Space' && e.target.tagName !== 'INPUT' && e.target.tagName !== 'SELECT') {
      e.preventDefault();
      setPlaying(!playing);
    }
  });
  const slider = document.getElementById('slider');
  slider.max = frames - 1;
  slider.addEventListener('input', () => {
    position = Number(slider.value);
    setFrame(position);
  });
  document.getElementById('speed').addEventListener('change', (e) => { speed = Number(e.target.value); });
  document.getElementById('reset').addEventListener('click', () => {
    userCamera = false;
    sceneCamera(frame);
    dirty = true;
  });

  function resize() {
    const w = view.clientWidth, h = view.clientHeight;
    renderer.setSize(w, h, false);
    camera.aspect = w / Math.max(1, h);
    camera.updateProjectionMatrix();
    dirty = true;
    if (map) map.resize();
  }
  window.addEventListener('resize', resize);

  function tick(now) {
    if (playing && frames > 1) {
      if (last !== null) position += ((now - last) / 1000) * D.fps * speed;
      last = now;
      if (position >= frames) position = 0; // plays on from the start
      setFrame(Math.floor(position));
    }
    if (dirty) {
      dirty = false;
      renderer.render(scene, camera);
    }
    requestAnimationFrame(tick);
  }

  // --- a session's Poincare map beside the view: its points by trajectory colour, zoomed and panned
  let map = null;
  if (D.map) map = new MapView(document.getElementById('map'), D.map);

  resize();
  setFrame(0);
  requestAnimationFrame(tick);

  window.rollviz = {
    data: D,
    webgl: webgl,
    frames: frames,
    frame: () => frame,
    time: (k) => times[k === undefined ? frame : k],
    state: (k) => Array.from(states.subarray(dim * (k === undefined ? frame : k), dim * ((k === undefined ? frame : k) + 1))),
    setFrame: (k) => { position = k; setFrame(k); },
    play: () => setPlaying(true),
    pause: () => setPlaying(false),
    playing: () => playing,
    // the matrix (column-major) an actor is drawn with now, by its name ("body", "plane", ...)
    matrix: (name) => {
      const a = actors.find((x) => x.name === name);
      if (!a) return null;
      const v = a.versions.find((x) => x.object.visible) || a.versions[a.versions.length - 1];
      return Array.from(v.object.matrix.elements);
    },
    // the vertices a growing actor (a trace) shows now
    shown: (name) => {
      const a = actors.find((x) => x.name === name);
      const v = a && a.versions.find((x) => x.object.visible);
      if (!v || !v.object.userData.line) return null;
      const g = v.object.userData.line.geometry;
      return Array.from(g.attributes.position.array.subarray(0, 3 * g.drawRange.count));
    },
    // a session's map: the ranges shown [x0, x1, y0, y1]
    mapRange: () => (map ? map.range() : null),
  };

  // ---------------------------------------------------------------------------------------------------------
  // The 2D fallback: every visible triangle, segment and dot projected by the same camera, clipped at the near
  // plane, sorted far to near and painted with one colour each (a textured face takes its texture's colour at
  // its centre), lit by the headlight as VTK lights a scene.
  function CanvasFallback() {
    const canvas = document.createElement('canvas');
    const ctx = canvas.getContext('2d');
    const faceColours = new Map(); // texture -> pixel reader
    this.domElement = canvas;
    this.info = { render: { frame: 0 } };
    this.setSize = (w, h) => {
      const r = window.devicePixelRatio || 1;
      canvas.width = Math.max(1, Math.round(w * r));
      canvas.height = Math.max(1, Math.round(h * r));
    };
    this.textureLoaded = (t) => {
      const c = document.createElement('canvas');
      c.width = t.image.width;
      c.height = t.image.height;
      const g = c.getContext('2d');
      g.drawImage(t.image, 0, 0);
      faceColours.set(t, { w: c.width, h: c.height, data: g.getImageData(0, 0, c.width, c.height).data });
    };
    const mvp = new THREE.Matrix4(), v = new THREE.Vector4(), a = new THREE.Vector3(), b = new THREE.Vector3(),
      n = new THREE.Vector3(), eye = new THREE.Vector3();
    this.render = (scene, camera) => {
      this.info.render.frame++;
      scene.updateMatrixWorld();
      camera.updateMatrixWorld();
      const W = canvas.width, H = canvas.height;
      ctx.clearRect(0, 0, W, H);
      camera.getWorldDirection(eye);
      const items = [];
      scene.traverseVisible((o) => {
        if (!(o.isMesh || o.isLine || o.isPoints)) return;
        const geo = o.geometry, pos = geo.attributes.position.array;
        const index = geo.index ? geo.index.array : null;
        const count = index ? index.length : Math.min(geo.drawRange.count, pos.length / 3);
        mvp.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse).multiply(o.matrixWorld);
        const m = o.material, base = m.color;
        const vertex = (i) => {
          v.set(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2], 1).applyMatrix4(mvp);
          return [v.x, v.y, v.z, v.w];
        };
        const colourOf = (r, g, bl, shade) =>
          `rgba(${Math.round(255 * Math.min(1, r * shade))},${Math.round(255 * Math.min(1, g * shade))},` +
          `${Math.round(255 * Math.min(1, bl * shade))},${m.opacity})`;
        const id = (k) => (index ? index[k] : k);
        if (o.isMesh) {
          const tex = m.map && faceColours.get(m.map);
          const t = triangles(geo), tp = t.positions, tuv = t.uvs;
          const at = (i) => {
            v.set(tp[3 * i], tp[3 * i + 1], tp[3 * i + 2], 1).applyMatrix4(mvp);
            return [v.x, v.y, v.z, v.w];
          };
          for (let k = 0; k + 2 < tp.length / 3; k += 3) {
            const poly = clip([at(k), at(k + 1), at(k + 2)]);
            if (poly.length < 3) continue;
            let shade = 1;
            if (m.isMeshPhongMaterial || m.isMeshLambertMaterial) {
              a.set(tp[3 * k + 3] - tp[3 * k], tp[3 * k + 4] - tp[3 * k + 1], tp[3 * k + 5] - tp[3 * k + 2]);
              b.set(tp[3 * k + 6] - tp[3 * k], tp[3 * k + 7] - tp[3 * k + 1], tp[3 * k + 8] - tp[3 * k + 2]);
              n.crossVectors(a, b).transformDirection(o.matrixWorld);
              shade = 0.22 + 0.85 * Math.abs(n.dot(eye));
            }
            let r = base.r, g = base.g, bl = base.b;
            if (tex && tuv) {
              let s = (tuv[2 * k] + tuv[2 * k + 2] + tuv[2 * k + 4]) / 3;
              let q = (tuv[2 * k + 1] + tuv[2 * k + 3] + tuv[2 * k + 5]) / 3;
              s -= Math.floor(s);
              q -= Math.floor(q);
              const px = Math.min(tex.w - 1, Math.floor(s * tex.w)), py = Math.min(tex.h - 1, Math.floor((1 - q) * tex.h));
              const c = 4 * (py * tex.w + px);
              r *= tex.data[c] / 255;
              g *= tex.data[c + 1] / 255;
              bl *= tex.data[c + 2] / 255;
            }
            items.push({ z: depth(poly), poly: poly, fill: colourOf(r, g, bl, shade) });
          }
        } else if (o.isLine) {
          const step = o.isLineSegments ? 2 : 1, stroke = colourOf(base.r, base.g, base.b, 1);
          for (let k = 0; k + 1 < count; k += step) {
            const p = vertex(id(k)), q = vertex(id(k + 1));
            if (p[3] <= 1e-9 || q[3] <= 1e-9) continue;
            items.push({ z: (p[2] / p[3] + q[2] / q[3]) / 2 - 1e-4, line: [p, q], stroke: stroke, width: m.linewidth || 1 });
          }
        } else {
          const fill = colourOf(base.r, base.g, base.b, 1);
          for (let k = 0; k < count; ++k) {
            const p = vertex(id(k));
            if (p[3] > 1e-9) items.push({ z: p[2] / p[3] - 2e-4, dot: p, fill: fill, size: m.size || 3 });
          }
        }
      });
      items.sort((p, q) => q.z - p.z);
      const X = (p) => ((p[0] / p[3] + 1) / 2) * W, Y = (p) => ((1 - p[1] / p[3]) / 2) * H;
      ctx.lineJoin = 'round';
      for (const it of items) {
        if (it.poly) {
          ctx.beginPath();
          ctx.moveTo(X(it.poly[0]), Y(it.poly[0]));
          for (let i = 1; i < it.poly.length; ++i) ctx.lineTo(X(it.poly[i]), Y(it.poly[i]));
          ctx.closePath();
          ctx.fillStyle = it.fill;
          ctx.strokeStyle = it.fill; // hides the seams between faces
          ctx.lineWidth = 0.8;
          ctx.fill();
          ctx.stroke();
        } else if (it.line) {
          ctx.beginPath();
          ctx.moveTo(X(it.line[0]), Y(it.line[0]));
          ctx.lineTo(X(it.line[1]), Y(it.line[1]));
          ctx.strokeStyle = it.stroke;
          ctx.lineWidth = it.width;
          ctx.stroke();
        } else {
          ctx.fillStyle = it.fill;
          ctx.fillRect(X(it.dot) - it.size / 2, Y(it.dot) - it.size / 2, it.size, it.size);
        }
      }
    };
    // A mesh's triangles, unindexed; a mesh of a few large triangles (the floor) cut into many, so that
    // sorting by depth stays right and a texture shows in the colours of its pieces.
    const pieces = new WeakMap();
    function triangles(geo) {
      let t = pieces.get(geo);
      if (t) return t;
      const pos = geo.attributes.position.array, uv = geo.attributes.uv ? geo.attributes.uv.array : null;
      const index = geo.index ? geo.index.array : Array.from({ length: pos.length / 3 }, (_, i) => i);
      const levels = index.length / 3 <= 16 ? 5 : 0;
      const P = [], U = [];
      const mid = (p, q) => p.map((x, i) => (x + q[i]) / 2);
      const cut = (p, u, level) => {
        if (level === 0) {
          for (const x of p) P.push(x[0], x[1], x[2]);
          if (uv) for (const x of u) U.push(x[0], x[1]);
          return;
        }
        const pm = [mid(p[0], p[1]), mid(p[1], p[2]), mid(p[2], p[0])];
        const um = uv ? [mid(u[0], u[1]), mid(u[1], u[2]), mid(u[2], u[0])] : [null, null, null];
        cut([p[0], pm[0], pm[2]], [u[0], um[0], um[2]], level - 1);
        cut([pm[0], p[1], pm[1]], [um[0], u[1], um[1]], level - 1);
        cut([pm[2], pm[1], p[2]], [um[2], um[1], u[2]], level - 1);
        cut([pm[0], pm[1], pm[2]], [um[0], um[1], um[2]], level - 1);
      };
      for (let k = 0; k + 2 < index.length; k += 3) {
        const ids = [index[k], index[k + 1], index[k + 2]];
        cut(ids.map((i) => [pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]]),
            ids.map((i) => (uv ? [uv[2 * i], uv[2 * i + 1]] : null)), levels);
      }
      t = { positions: new Float32Array(P), uvs: uv ? new Float32Array(U) : null };
      pieces.set(geo, t);
      return t;
    }
    // a polygon in clip coordinates cut by the near plane (z > -w): Sutherland & Hodgman, one plane
    function clip(poly) {
      const out = [];
      for (let i = 0; i < poly.length; ++i) {
        const p = poly[i], q = poly[(i + 1) % poly.length];
        const dp = p[2] + p[3], dq = q[2] + q[3];
        if (dp >= 0) out.push(p);
        if ((dp >= 0) !== (dq >= 0)) {
          const s = dp / (dp - dq);
          out.push([0, 1, 2, 3].map((c) => p[c] + s * (q[c] - p[c])));
        }
      }
      for (const p of out) if (p[3] <= 1e-12) return [];
      return out;
    }
    function depth(poly) {
      let z = 0;
      for (const p of poly) z += p[2] / p[3];
      return z / poly.length;
    }
  }

  // ---------------------------------------------------------------------------------------------------------
  function MapView(box, M) {
    box.classList.remove('hidden');
    const canvas = document.createElement('canvas');
    box.insertBefore(canvas, box.firstChild);
    const ctx = canvas.getContext('2d');
    const series = M.series.map((s) => ({ kind: s.kind, colour: css(s.colour), x: f64(s.x), y: f64(s.y) }));
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (const s of series)
      for (let i = 0; i < s.x.length; ++i) {
        if (!Number.isFinite(s.x[i]) || !Number.isFinite(s.y[i])) continue;
        lo = [Math.min(lo[0], s.x[i]), Math.min(lo[1], s.y[i])];
        hi = [Math.max(hi[0], s.x[i]), Math.max(hi[1], s.y[i])];
      }
    if (!(lo[0] < hi[0])) (lo[0] -= 1), (hi[0] += 1);
    if (!(lo[1] < hi[1])) (lo[1] -= 1), (hi[1] += 1);
    const margin = [0.04 * (hi[0] - lo[0]), 0.04 * (hi[1] - lo[1])];
    const whole = [lo[0] - margin[0], hi[0] + margin[0], lo[1] - margin[1], hi[1] + margin[1]];
    let range = whole.slice();
    const pad = { l: 58, r: 12, t: 12, b: 40 };
    const ratio = () => window.devicePixelRatio || 1;
    this.resize = () => {
      canvas.width = Math.max(1, Math.round(box.clientWidth * ratio()));
      canvas.height = Math.max(1, Math.round(box.clientHeight * ratio()));
      draw();
    };
    const plotW = () => canvas.width / ratio() - pad.l - pad.r, plotH = () => canvas.height / ratio() - pad.t - pad.b;
    const sx = (x) => pad.l + ((x - range[0]) / (range[1] - range[0])) * plotW();
    const sy = (y) => pad.t + (1 - (y - range[2]) / (range[3] - range[2])) * plotH();
    function ticks(a, b) {
      const step = Math.pow(10, Math.floor(Math.log10((b - a) / 5)));
      const s = [1, 2, 5, 10].map((m) => m * step).find((m) => (b - a) / m <= 7);
      const out = [];
      for (let v = Math.ceil(a / s) * s; v <= b + 1e-9 * s; v += s) out.push(Math.abs(v) < 1e-12 * s ? 0 : v);
      return { values: out, digits: Math.max(0, -Math.floor(Math.log10(s))) };
    }
    function draw() {
      const r = ratio();
      ctx.setTransform(r, 0, 0, r, 0, 0);
      ctx.clearRect(0, 0, canvas.width, canvas.height);
      ctx.strokeStyle = '#c9ccd4';
      ctx.fillStyle = '#4a5160';
      ctx.font = '12px system-ui, sans-serif';
      const tx = ticks(range[0], range[1]), ty = ticks(range[2], range[3]);
      ctx.textAlign = 'center';
      for (const v of tx.values) {
        ctx.beginPath(); ctx.moveTo(sx(v), pad.t); ctx.lineTo(sx(v), pad.t + plotH()); ctx.stroke();
        ctx.fillText(v.toFixed(tx.digits), sx(v), pad.t + plotH() + 15);
      }
      ctx.textAlign = 'right';
      for (const v of ty.values) {
        ctx.beginPath(); ctx.moveTo(pad.l, sy(v)); ctx.lineTo(pad.l + plotW(), sy(v)); ctx.stroke();
        ctx.fillText(v.toFixed(ty.digits), pad.l - 5, sy(v) + 4);
      }
      ctx.textAlign = 'center';
      ctx.fillText(M.x, pad.l + plotW() / 2, pad.t + plotH() + 32);
      ctx.save(); ctx.translate(14, pad.t + plotH() / 2); ctx.rotate(-Math.PI / 2); ctx.fillText(M.y, 0, 0); ctx.restore();
      ctx.save();
      ctx.beginPath(); ctx.rect(pad.l, pad.t, plotW(), plotH()); ctx.clip();
      for (const s of series) {
        ctx.fillStyle = ctx.strokeStyle = s.colour;
        if (s.kind === 'curve') {
          ctx.beginPath();
          for (let i = 0; i < s.x.length; ++i) (i ? ctx.lineTo : ctx.moveTo).call(ctx, sx(s.x[i]), sy(s.y[i]));
          ctx.lineWidth = 1.5; ctx.stroke();
        } else {
          const size = s.kind === 'markers' ? 7 : 1.6;
          for (let i = 0; i < s.x.length; ++i) ctx.fillRect(sx(s.x[i]) - size / 2, sy(s.y[i]) - size / 2, size, size);
        }
      }
      ctx.restore();
    }
    const at = (e) => {
      const b = canvas.getBoundingClientRect();
      return [range[0] + ((e.clientX - b.left - pad.l) / plotW()) * (range[1] - range[0]),
              range[2] + (1 - (e.clientY - b.top - pad.t) / plotH()) * (range[3] - range[2])];
    };
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      const [x, y] = at(e), f = Math.exp(0.0015 * e.deltaY);
      range = [x + (range[0] - x) * f, x + (range[1] - x) * f, y + (range[2] - y) * f, y + (range[3] - y) * f];
      draw();
    }, { passive: false });
    let drag = null;
    canvas.addEventListener('mousedown', (e) => { drag = at(e); });
    window.addEventListener('mouseup', () => { drag = null; });
    canvas.addEventListener('mousemove', (e) => {
      if (!drag) return;
      const [x, y] = at(e);
      range = [range[0] - (x - drag[0]), range[1] - (x - drag[0]), range[2] - (y - drag[1]), range[3] - (y - drag[1])];
      draw();
    });
    canvas.addEventListener('dblclick', () => { range = whole.slice(); draw(); });
    this.range = () => range.slice();
  }
})();
