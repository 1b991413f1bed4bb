// The ray tree of a pixel in 3D over its scene: raylab's answer to MIT 6.837's RayTree viewer.
// Hand-written WebGL 1, no library: the page draws triangles and lines that the grader computed
// (it tessellates the scene and walks the tree; nothing is traced here). Offline, one file.
//
//   raylabView3d(root, data)  fills `root` with a canvas, its controls and the trees as text,
//                             and returns {show(trees), pick(x, y)}.
//
// data: {title, camera: {eye, at, up, fovy}, radius, objects: [{name, color, triangles}],
//        lights: [segments of 6 numbers], trees: [{label, pixel, text, segments:
//        [{kind, from, to, weight, hit}]}], and in the report grid: {step, expected: [trees],
//        yours: [trees]}, the trees of every step-th pixel}. Mouse: drag orbits, shift-drag or
// right-drag pans, the wheel zooms. `pick` shows the grid's trees nearest pixel (x, y).
"use strict";

window.raylabView3d = function (root, data) {
  const RAY_COLORS = {
    eye: [0.94, 0.94, 0.94],
    reflected: [0.31, 0.76, 0.97],
    transmitted: [0.78, 0.49, 1.0],
    shadow: [1.0, 0.84, 0.31],
    blocked: [1.0, 0.32, 0.32],
  };
  const BACKGROUND = [0.125, 0.141, 0.157];

  root.classList.add("view3d");
  const canvas = document.createElement("canvas");
  canvas.width = 720;
  canvas.height = 480;
  const controls = document.createElement("div");
  controls.className = "view3d-controls";
  root.append(canvas, controls);
  const gl = canvas.getContext("webgl", { antialias: true, preserveDrawingBuffer: true });
  if (!gl) {
    root.append(text("p", "This browser gives no WebGL: the ray trees are below as text."));
  }

  // The controls: surfaces as faces or edges, each tree shown or not, a legend.
  const state = { wire: false, shown: [], hiddenKinds: new Set() };
  const wire = checkbox("wireframe", false, (on) => { state.wire = on; draw(); });
  const treeBoxes = document.createElement("span");
  controls.append(wire, treeBoxes);
  const legend = document.createElement("div");
  legend.className = "view3d-legend";
  for (const [kind, name] of [["eye", "eye"], ["shadow", "shadow, reaches the light"],
    ["blocked", "shadow, blocked"], ["reflected", "reflected"], ["transmitted", "transmitted"]]) {
    // A click on a kind hides its rays, or shows them again.
    const key = document.createElement("span");
    key.style.color = css(RAY_COLORS[kind]);
    key.style.cursor = "pointer";
    key.dataset.kind = kind;
    key.title = "show or hide these rays";
    key.textContent = "━ " + name;
    key.addEventListener("click", () => {
      const hide = !state.hiddenKinds.has(kind);
      if (hide) state.hiddenKinds.add(kind); else state.hiddenKinds.delete(kind);
      key.style.opacity = hide ? 0.4 : 1;
      draw();
    });
    legend.append(key);
  }
  legend.append(text("span", "click a kind: hide or show it · drag: orbit · shift-drag: pan · wheel: zoom"));
  root.append(legend);
  const texts = document.createElement("div");
  texts.className = "view3d-texts";
  root.append(texts);
  // The trees shown: a checkbox and the text of each (the first in full colour, the second a shade
  // lighter), and their lines once there is WebGL.
  let trees = [];
  function show(list) {
    state.shown = list.map(() => true);
    treeBoxes.replaceChildren(...list.map((tree, i) => {
      const label = tree.label + (i > 0 ? ", lighter" : "") + " (pixel " + tree.pixel[0] + ", " + tree.pixel[1] + ")";
      return checkbox(label, true, (on) => { state.shown[i] = on; draw(); }, "tree-" + i);
    }));
    texts.replaceChildren(...list.map((tree) =>
      text("pre", tree.label + ", pixel (" + tree.pixel[0] + ", " + tree.pixel[1] + "):\n" + tree.text)));
    root.dataset.pixel = list.length > 0 ? list[0].pixel.join(",") : "";
    if (gl) {
      trees = list.map(treeLines);
      draw();
    }
  }
  // The grid's pair of trees nearest pixel (x, y): the centre of the step × step block it lies in.
  function pick(x, y) {
    const grid = data.grid;
    if (!grid || grid.expected.length === 0) return null;
    const last = grid.expected[grid.expected.length - 1].pixel;
    const centre = (v, max) => Math.min(Math.floor(v / grid.step) * grid.step + grid.step / 2, max);
    const at = [centre(x, last[0]), centre(y, last[1])];
    const i = grid.expected.findIndex((t) => t.pixel[0] === at[0] && t.pixel[1] === at[1]);
    if (i < 0) return null;
    show([grid.expected[i], grid.yours[i]]);
    return at;
  }
  const api = { show, pick, step: data.grid ? data.grid.step : null };
  if (!gl) {
    show(data.trees);
    return api;
  }

  // Two programs: lit flat faces, and unlit coloured lines and points.
  const faces = program(
    "attribute vec3 p; attribute vec3 n; uniform mat4 m; varying vec3 vn;" +
      "void main() { vn = n; gl_Position = m * vec4(p, 1.0); }",
    "precision mediump float; uniform vec3 color; uniform float opacity; uniform vec3 toEye; varying vec3 vn;" +
      "void main() { float l = 0.35 + 0.65 * abs(dot(normalize(vn), toEye));" +
      " gl_FragColor = vec4(color * l, opacity); }");
  const lines = program(
    "attribute vec3 p; attribute vec4 c; uniform mat4 m; varying vec4 vc;" +
      "void main() { vc = c; gl_Position = m * vec4(p, 1.0); gl_PointSize = 5.0; }",
    "precision mediump float; uniform float alpha; varying vec4 vc;" +
      "void main() { gl_FragColor = vec4(vc.rgb, vc.a * alpha); }");

  // Each object: its faces (with flat normals) and its edges, as buffers.
  const objects = data.objects.map((object) => {
    const t = object.triangles;
    const normals = new Float32Array(t.length);
    const edges = new Float32Array(t.length * 2);
    for (let i = 0; i < t.length; i += 9) {
      const a = [t[i], t[i + 1], t[i + 2]], b = [t[i + 3], t[i + 4], t[i + 5]], c = [t[i + 6], t[i + 7], t[i + 8]];
      const nrm = normalize(cross(sub(b, a), sub(c, a)));
      for (let k = 0; k < 3; k++) normals.set(nrm, i + 3 * k);
      edges.set([...a, ...b, ...b, ...c, ...c, ...a], 2 * i);
    }
    return { color: object.color, opacity: object.opacity, count: t.length / 3, faces: buffer(t), normals: buffer(normals),
      edges: buffer(edges), edgeCount: edges.length / 3 };
  });

  // A tree: for each kind of ray, its segments as coloured lines and its hits as points.
  function treeLines(tree, i) {
    // A second tree (yours beside the expected) a shade lighter, so that the two read apart.
    const tint = i === 0 ? 1.0 : 0.6;
    const kinds = {};
    for (const s of tree.segments) {
      const kind = s.kind === "shadow" && s.hit !== null ? "blocked" : s.kind;
      const color = RAY_COLORS[kind].map((x) => x * tint + (1 - tint));
      const k = kinds[kind] || (kinds[kind] = { positions: [], colors: [], points: [], pointColors: [] });
      k.positions.push(...s.from, ...s.to);
      k.colors.push(...color, 1, ...color, 1);
      if (s.hit !== null) {
        k.points.push(...s.to);
        k.pointColors.push(...color, 1);
      }
    }
    return Object.entries(kinds).map(([kind, k]) => ({ kind,
      lines: { positions: buffer(k.positions), colors: buffer(k.colors), count: k.positions.length / 3 },
      points: { positions: buffer(k.points), colors: buffer(k.pointColors), count: k.points.length / 3 } }));
  }
  const lights = data.lights.flat();
  const lightLines = { positions: buffer(lights), count: lights.length / 3,
    colors: buffer(Array.from({ length: lights.length / 3 }, () => [1, 0.95, 0.6, 1]).flat()) };

  // The orbit: the camera's offset from the point it looks at, turned about `up`.
  // It looks at the first tree's first hit (else, or when that lies far outside the scene's
  // bounds, where the scene's camera looks), from beside the scene's camera, a little turned and
  // raised: from the camera itself the eye ray would be a point, and from its height a floor
  // would be seen edge on.
  const up = normalize(data.camera.up);
  const first = data.trees.length > 0 && data.trees[0].segments[0];
  const near = first && first.hit !== null && length(sub(first.to, data.camera.at)) <= 2 * data.radius;
  const at = near ? first.to : data.camera.at;
  const turned = rotate(sub(data.camera.eye, at), up, 0.5);
  const raised = rotate(turned, normalize(cross(turned, up)), 0.35);
  const camera = { at: at.slice(), up, fovy: data.camera.fovy,
    offset: Math.abs(dot(normalize(raised), up)) < 0.995 ? raised : turned };
  let drag = null;
  canvas.addEventListener("contextmenu", (e) => e.preventDefault());
  canvas.addEventListener("mousedown", (e) => { drag = { x: e.clientX, y: e.clientY, pan: e.shiftKey || e.button === 2 }; });
  window.addEventListener("mouseup", () => { drag = null; });
  window.addEventListener("mousemove", (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX;
    drag.y = e.clientY;
    const right = normalize(cross(camera.offset, camera.up));
    if (drag.pan) {
      const scale = length(camera.offset) / canvas.clientHeight;
      const upOnScreen = normalize(cross(right, camera.offset));
      camera.at = add(camera.at, add(scale_(right, dx * scale), scale_(upOnScreen, dy * scale)));
    } else {
      let offset = rotate(camera.offset, camera.up, -dx * 0.01);
      const tilted = rotate(offset, right, -dy * 0.01);
      // Never over the pole: the view would flip.
      if (Math.abs(dot(normalize(tilted), camera.up)) < 0.995) offset = tilted;
      camera.offset = offset;
    }
    draw();
  });
  canvas.addEventListener("wheel", (e) => {
    e.preventDefault();
    camera.offset = scale_(camera.offset, Math.exp(e.deltaY * 0.001));
    draw();
  }, { passive: false });

  show(data.trees);
  return api;

  function draw() {
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(...BACKGROUND, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    const eye = add(camera.at, camera.offset);
    const distance = length(camera.offset);
    const near = Math.max(distance * 1e-3, 1e-4), far = distance + 4 * data.radius + 1;
    const m = multiply(perspective(camera.fovy, canvas.width / canvas.height, near, far),
      lookAt(eye, camera.at, camera.up));
    gl.enable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    if (state.wire) {
      gl.useProgram(lines.program);
      gl.uniformMatrix4fv(lines.m, false, m);
      gl.uniform1f(lines.alpha, 1);
      for (const o of objects) {
        gl.disableVertexAttribArray(lines.c);
        gl.vertexAttrib4f(lines.c, ...o.color, 1);
        attribute(lines.p, o.edges, 3);
        gl.drawArrays(gl.LINES, 0, o.edgeCount);
      }
    } else {
      gl.useProgram(faces.program);
      gl.uniformMatrix4fv(faces.m, false, m);
      gl.uniform3fv(faces.toEye, normalize(camera.offset));
      // The opaque objects, then the transparent ones over them, blended and hiding nothing.
      for (const translucent of [false, true]) {
        if (translucent) {
          gl.enable(gl.BLEND);
          gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
          gl.depthMask(false);
        }
        for (const o of objects) {
          if ((o.opacity < 1) !== translucent) continue;
          gl.uniform3fv(faces.color, o.color);
          gl.uniform1f(faces.opacity, o.opacity);
          attribute(faces.p, o.faces, 3);
          attribute(faces.n, o.normals, 3);
          gl.drawArrays(gl.TRIANGLES, 0, o.count);
        }
      }
      gl.depthMask(true);
      gl.disableVertexAttribArray(faces.n);
    }
    // Rays over the surfaces: in full where seen, faintly where a surface hides them.
    gl.useProgram(lines.program);
    gl.uniformMatrix4fv(lines.m, false, m);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    for (const [depth, alpha] of [[true, 1.0], [false, 0.3]]) {
      if (depth) gl.enable(gl.DEPTH_TEST); else gl.disable(gl.DEPTH_TEST);
      gl.uniform1f(lines.alpha, alpha);
      lineSet(lightLines, gl.LINES);
      trees.forEach((kinds, i) => {
        if (!state.shown[i]) return;
        for (const k of kinds) {
          if (state.hiddenKinds.has(k.kind)) continue;
          lineSet(k.lines, gl.LINES);
          lineSet(k.points, gl.POINTS);
        }
      });
    }
  }

  function lineSet(set, mode) {
    if (set.count === 0) return;
    gl.enableVertexAttribArray(lines.c);
    attribute(lines.p, set.positions, 3);
    attribute(lines.c, set.colors, 4);
    gl.drawArrays(mode, 0, set.count);
  }

  function attribute(location, b, size) {
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.enableVertexAttribArray(location);
    gl.vertexAttribPointer(location, size, gl.FLOAT, false, 0, 0);
  }

  function buffer(values) {
    const b = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, values instanceof Float32Array ? values : new Float32Array(values), gl.STATIC_DRAW);
    return b;
  }

  function program(vertex, fragment) {
    const p = gl.createProgram();
    for (const [type, source] of [[gl.VERTEX_SHADER, vertex], [gl.FRAGMENT_SHADER, fragment]]) {
      const s = gl.createShader(type);
      gl.shaderSource(s, source);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
      gl.attachShader(p, s);
    }
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
    const found = { program: p };
    for (const name of ["p", "n", "c"]) found[name] = gl.getAttribLocation(p, name);
    for (const name of ["m", "color", "opacity", "toEye", "alpha"]) found[name] = gl.getUniformLocation(p, name);
    return found;
  }

  function checkbox(label, on, changed, id) {
    const box = document.createElement("label");
    const input = document.createElement("input");
    input.type = "checkbox";
    input.checked = on;
    if (id) input.dataset.view = id;
    input.addEventListener("change", () => changed(input.checked));
    box.append(input, " " + label);
    return box;
  }

  function text(tag, content) {
    const e = document.createElement(tag);
    e.textContent = content;
    return e;
  }

  function css(c) {
    return "rgb(" + c.map((x) => Math.round(255 * x)).join(",") + ")";
  }
};

// Vectors as arrays of 3, matrices as Float32Arrays of 16 in column-major order (WebGL's).
function add(a, b) { return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]; }
function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
function scale_(a, s) { return [a[0] * s, a[1] * s, a[2] * s]; }
function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
function length(a) { return Math.sqrt(dot(a, a)); }
function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
function normalize(a) { const l = length(a); return l > 0 ? scale_(a, 1 / l) : [0, 0, 1]; }

// `v` turned by `angle` about the unit `axis` (Rodrigues).
function rotate(v, axis, angle) {
  const c = Math.cos(angle), s = Math.sin(angle);
  return add(add(scale_(v, c), scale_(cross(axis, v), s)), scale_(axis, dot(axis, v) * (1 - c)));
}

function perspective(fovy, aspect, near, far) {
  const f = 1 / Math.tan(fovy / 2);
  const m = new Float32Array(16);
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (far + near) / (near - far);
  m[11] = -1;
  m[14] = (2 * far * near) / (near - far);
  return m;
}

function lookAt(eye, at, up) {
  const z = normalize(sub(eye, at)), x = normalize(cross(up, z)), y = cross(z, x);
  return new Float32Array([x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0,
    -dot(x, eye), -dot(y, eye), -dot(z, eye), 1]);
}

function multiply(a, b) {
  const m = new Float32Array(16);
  for (let col = 0; col < 4; col++) {
    for (let row = 0; row < 4; row++) {
      let sum = 0;
      for (let k = 0; k < 4; k++) sum += a[k * 4 + row] * b[col * 4 + k];
      m[col * 4 + row] = sum;
    }
  }
  return m;
}
