// The 3D view (three.js): the eye O, the pane with the selected pixel, every
// sphere, plane and light, the pixel's ray and its hit point P, the normal N,
// the light vectors K, shadow rays and their blocker, R and V where Phong
// runs, each labelled with the article's symbol in the colour the
// derivation gives it. The current step's quantity is drawn bold, the
// others faint. Drawn only when something changes (no animation loop).
//
// The article's axes: x right, y up, the eye looking along +z. three.js looks
// along −z, so a point (x, y, z) is drawn at (x, y, −z).
import {
  AmbientLight, BufferGeometry, CircleGeometry, ConeGeometry, CylinderGeometry, DirectionalLight, DoubleSide, Group,
  Line, LineBasicMaterial, Mesh, MeshBasicMaterial, MeshLambertMaterial, PerspectiveCamera, PlaneGeometry, Quaternion,
  Scene, SphereGeometry, Vector3, WebGLRenderer, EdgesGeometry, LineSegments,
} from 'three';
import { quantityColour } from './colours.js';
import { timed } from './timing.js';
import { t } from './words.js';

const toThree = (v) => new Vector3(v[0], v[1], -v[2]);
// Back to the article's coordinates (what the list under the view reports).
const fromThree = (v) => [v.x, v.y, -v.z];

// Parses an English full-digit number text of the formatter ("−0.125", "1e-07").
export const numberOf = (text) => Number(String(text).replace(/\u2212/g, '-'));

export class View3D {
  constructor(canvas, labels, list) {
    this.canvas = canvas;
    this.labels = labels;
    this.list = list; // what is drawn, in words (and for a reader without the canvas)
    // A browser without WebGL (switched off, or no graphics driver: Firefox
    // headless here) still gets the rest of the page and the list of what the
    // view would draw, in words; the canvas is hidden (available: false).
    // Asked of a scratch canvas first: three.js reports a failure on the
    // console before it throws, and the page's own canvas keeps its options.
    const webgl2 = document.createElement('canvas').getContext('webgl2');
    try {
      if (!webgl2) throw new Error('no WebGL 2');
      this.renderer = new WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
      this.renderer.setClearColor(0xf4f4f0);
    } catch {
      this.renderer = null;
    }
    this.available = this.renderer !== null;
    if (!this.available) {
      canvas.hidden = true;
      canvas.parentElement.hidden = true; // the frame and its labels
      canvas.removeAttribute('tabindex');
    }
    this.scene = new Scene();
    this.scene.add(new AmbientLight(0xffffff, 1.2));
    const sun = new DirectionalLight(0xffffff, 1.5);
    sun.position.set(3, 5, 4);
    this.scene.add(sun);
    this.camera = new PerspectiveCamera(45, 1, 0.05, 200);
    // From the right of the eye and a little above: the ray runs across the view.
    this.orbit = { theta: 1.15, phi: 1.2, radius: 5.5, target: new Vector3(0.3, 0, -2.3) };
    this.world = new Group();
    this.pixelGroup = new Group();
    this.scene.add(this.world, this.pixelGroup);
    this.marks = []; // {object, key, label}
    this.bindControls();
    new ResizeObserver(() => this.render()).observe(canvas);
  }

  bindControls() {
    // Pointers down on the canvas (mouse, pen or fingers): one turns the view,
    // two pinch it nearer or farther (a tablet has no wheel). The canvas's
    // touch-action: none keeps the browser from scrolling the page instead.
    const down = new Map(); // pointerId -> {x, y}
    let spread = 0; // the two fingers' distance at the last move
    const distance = () => {
      const [a, b] = [...down.values()];
      return Math.hypot(a.x - b.x, a.y - b.y);
    };
    this.canvas.addEventListener('pointerdown', (event) => {
      down.set(event.pointerId, { x: event.clientX, y: event.clientY });
      this.canvas.setPointerCapture(event.pointerId);
      if (down.size === 2) spread = distance();
    });
    this.canvas.addEventListener('pointermove', (event) => {
      const last = down.get(event.pointerId);
      if (!last) return;
      const now = { x: event.clientX, y: event.clientY };
      down.set(event.pointerId, now);
      if (down.size === 1) {
        this.turn((now.x - last.x) * -0.01, (now.y - last.y) * -0.01);
      } else if (down.size === 2) {
        const apart = distance();
        // Fingers moving apart bring the view nearer, as on a map.
        if (spread > 0 && apart > 0) this.zoom(spread / apart);
        spread = apart;
      }
    });
    const up = (event) => {
      down.delete(event.pointerId);
      spread = down.size === 2 ? distance() : 0;
    };
    this.canvas.addEventListener('pointerup', up);
    this.canvas.addEventListener('pointercancel', up);
    this.canvas.addEventListener('wheel', (event) => {
      event.preventDefault();
      this.zoom(event.deltaY > 0 ? 1.1 : 1 / 1.1);
    }, { passive: false });
    this.canvas.addEventListener('keydown', (event) => {
      const keys = {
        ArrowLeft: () => this.turn(0.1, 0), ArrowRight: () => this.turn(-0.1, 0),
        ArrowUp: () => this.turn(0, 0.1), ArrowDown: () => this.turn(0, -0.1),
        '+': () => this.zoom(1 / 1.1), '=': () => this.zoom(1 / 1.1), '-': () => this.zoom(1.1),
      };
      if (!keys[event.key]) return;
      event.preventDefault();
      event.stopPropagation();
      keys[event.key]();
    });
  }

  turn(dTheta, dPhi) {
    this.orbit.theta += dTheta;
    this.orbit.phi = Math.min(Math.PI - 0.05, Math.max(0.05, this.orbit.phi + dPhi));
    this.render();
  }

  zoom(factor) {
    this.orbit.radius = Math.min(60, Math.max(1, this.orbit.radius * factor));
    this.render();
  }

  // The scene itself (scene_content of promyk_open_scene).
  setScene(content) {
    this.world.clear();
    const zE = content.z_E ?? 2;
    const faint = (colour, opacity) => new MeshLambertMaterial({ color: colour, transparent: true, opacity, side: DoubleSide });
    this.zE = zE;
    // The eye O and the pane of side 2 at z = z_E.
    const eye = new Mesh(new SphereGeometry(0.06, 16, 12), new MeshBasicMaterial({ color: 0x000000 }));
    this.world.add(eye);
    const pane = new Mesh(new PlaneGeometry(2, 2), new MeshBasicMaterial({ color: 0x888888, transparent: true, opacity: 0.15, side: DoubleSide }));
    pane.position.copy(toThree([0, 0, zE]));
    const edges = new LineSegments(new EdgesGeometry(new PlaneGeometry(2, 2)), new LineBasicMaterial({ color: 0x444444 }));
    edges.position.copy(pane.position);
    this.world.add(pane, edges);
    this.fixedLabels = [{ text: 'O', at: new Vector3(0, 0, 0), colour: '#000' }];
    const materials = content.materials || [];
    const colourOf = (index) => {
      const m = materials[index];
      const c = m && m.colour ? m.colour : [0.75, 0.75, 0.75];
      return (Math.round(c[0] * 255) << 16) | (Math.round(c[1] * 255) << 8) | Math.round(c[2] * 255);
    };
    this.objects = { sphere: [], plane: [] };
    (content.spheres || []).forEach((sphere, k) => {
      const mesh = new Mesh(new SphereGeometry(sphere.r, 48, 32), faint(colourOf(sphere.material), 0.45));
      mesh.position.copy(toThree(sphere.S));
      this.world.add(mesh);
      this.objects.sphere.push(mesh);
      this.fixedLabels.push({ text: (content.spheres.length > 1 ? `S${k}` : 'S'), at: toThree(sphere.S), colour: '#333' });
    });
    (content.planes || []).forEach((plane) => {
      const mesh = new Mesh(new PlaneGeometry(12, 12), faint(colourOf(plane.material), 0.3));
      const normal = toThree(plane.n).normalize();
      mesh.quaternion.copy(new Quaternion().setFromUnitVectors(new Vector3(0, 0, 1), normal));
      const q = toThree(plane.Q);
      mesh.position.copy(q).add(new Vector3(0, 0, -4).projectOnPlane(normal));
      this.world.add(mesh);
      this.objects.plane.push(mesh);
    });
    this.lights = (content.lights || []).map((light, k) => {
      const mesh = new Mesh(new SphereGeometry(0.1, 16, 12), new MeshBasicMaterial({ color: 0xf0c000 }));
      mesh.position.copy(toThree(light.L));
      this.world.add(mesh);
      this.fixedLabels.push({ text: content.lights.length > 1 ? `L${k}` : 'L', at: mesh.position.clone(), colour: '#8a6d00' });
      return mesh.position.clone();
    });
    this.render();
  }

  // A bold-able segment from a to b (three.js coordinates).
  segment(a, b, colour, head) {
    const group = new Group();
    const length = a.distanceTo(b);
    if (!(length > 1e-9)) return group;
    const direction = b.clone().sub(a).normalize();
    const along = new Quaternion().setFromUnitVectors(new Vector3(0, 1, 0), direction);
    const headLength = head ? Math.min(0.18, length * 0.4) : 0;
    const shaft = new Mesh(new CylinderGeometry(0.012, 0.012, length - headLength, 8), new MeshBasicMaterial({ color: colour, transparent: true }));
    shaft.quaternion.copy(along);
    shaft.position.copy(a).addScaledVector(direction, (length - headLength) / 2);
    group.add(shaft);
    if (head) {
      const cone = new Mesh(new ConeGeometry(0.045, headLength, 12), new MeshBasicMaterial({ color: colour, transparent: true }));
      cone.quaternion.copy(along);
      cone.position.copy(b).addScaledVector(direction, -headLength / 2);
      group.add(cone);
    }
    return group;
  }

  // A dashed segment from a to b: a shadow ray, apart from K's solid arrow.
  dashed(a, b, colour) {
    const group = new Group();
    const length = a.distanceTo(b);
    const dash = 0.07;
    const gap = 0.05;
    for (let at = 0; at < length; at += dash + gap) {
      const piece = this.segment(a.clone().lerp(b, at / length), a.clone().lerp(b, Math.min(length, at + dash) / length), colour, false);
      piece.children.forEach((c) => {
        c.geometry = new CylinderGeometry(0.02, 0.02, c.geometry.parameters.height, 6);
      });
      group.add(...piece.children);
    }
    return group;
  }

  // The selected pixel's geometry, from its view with every digit in English
  // (view.steps: key, group, components_full / value_full); `shown` is the
  // same trace's view in the page's language (for the words under the view).
  setPixel(view, w, shown) {
    this.pixelGroup.clear();
    this.marks = [];
    this.list.replaceChildren();
    if (!view) return this.render();
    const groups = view.groups || [];
    const ancestor = (step, kind) => {
      for (let g = step.group; g >= 0 && g < groups.length; g = groups[g].parent) if (groups[g].kind === kind) return groups[g].index;
      // The article's scene has one light and no light groups: its steps are light 0's.
      return kind === 'light' && !groups.some((g) => g.kind === 'light') ? 0 : -1;
    };
    const vec = (step) => (step && step.components_full ? step.components_full.map(numberOf) : null);
    const steps = view.steps;
    const first = (key) => steps.find((s) => s.key === key && ancestor(s, 'sample') <= 0);
    const shownOf = (step) => (shown && shown.steps[steps.indexOf(step)]) || step;
    // Each thing drawn, with its line in the list under the view: what it
    // is, and where it runs (article coordinates, every digit, in data-*).
    const add = (object, keys, label, at, colour, item) => {
      this.pixelGroup.add(object);
      this.marks.push({ object, keys, label, at, colour });
      if (!item) return;
      const line = document.createElement('li');
      line.dataset.kind = item.kind;
      if (item.light !== undefined) line.dataset.light = String(item.light);
      for (const [name, point] of Object.entries(item.points || {})) line.dataset[name] = fromThree(point).join(',');
      for (const [name, value] of Object.entries(item.data || {})) line.dataset[name] = String(value);
      const symbol = document.createElement('b');
      symbol.textContent = label || item.symbol || '';
      symbol.style.color = colour || '#000';
      line.append(symbol, ` ${item.text}`);
      this.list.append(line);
    };
    // The pixel on the pane.
    const { i, j } = view.header;
    const size = 2 / w;
    const pixel = new Mesh(new PlaneGeometry(size, size), new MeshBasicMaterial({ color: 0xf0e442, side: DoubleSide, transparent: true }));
    pixel.position.copy(toThree([(2 * j + 1) / w - 1, -(2 * i + 1) / w + 1, this.zE - 1e-3]));
    const frame = new LineSegments(new EdgesGeometry(new PlaneGeometry(size * 1.6, size * 1.6)), new LineBasicMaterial({ color: 0x000000 }));
    frame.position.copy(pixel.position);
    this.pixelGroup.add(frame);
    add(pixel, ['E'], null);
    const E = vec(first('E'));
    const P = vec(first('P'));
    const origin = new Vector3(0, 0, 0);
    const colourE = quantityColour('E');
    if (E) {
      const end = P ? toThree(P) : toThree(E).multiplyScalar(4);
      add(this.segment(origin, end, colourE, !P), ['E', 't', 't_hit', 'EE', 'C', 'delta', 'Delta', 'sqrt_Delta'], 'E',
        toThree(E), colourE, { kind: 'ray', text: t(P ? 'page_draw_ray_hit' : 'page_draw_ray_miss'), points: { from: origin, to: end } });
    }
    if (P) {
      const p = toThree(P);
      const dot = new Mesh(new SphereGeometry(0.05, 16, 12), new MeshBasicMaterial({ color: quantityColour('P'), transparent: true }));
      dot.position.copy(p);
      add(dot, ['P'], 'P', p, quantityColour('P'), { kind: 'P', text: t('page_draw_P'), points: { at: p } });
      const N = vec(first('N_P')) || vec(first('n_hat'));
      if (N) {
        const tip = p.clone().add(toThree(N).normalize().multiplyScalar(0.7));
        add(this.segment(p, tip, quantityColour('N'), true), ['N', 'N_P', 'n_hat'], 'N', tip, quantityColour('N'),
          { kind: 'N', text: t('page_draw_N'), points: { from: p, to: tip } });
      }
      const V = vec(first('V_hat'));
      if (V) {
        const tip = p.clone().add(toThree(V).normalize().multiplyScalar(0.7));
        add(this.segment(p, tip, quantityColour('V_hat'), true), ['V_hat'], 'V', tip, quantityColour('V_hat'),
          { kind: 'V', text: t('page_draw_V'), points: { from: p, to: tip } });
      }
      // Per light: K from P to the light; its shadow ray (P + sK, 0 < s < 1)
      // with the test's result; R.
      const lightName = (light) => (this.lights.length > 1 ? `L${light}` : 'L');
      const shadowKeys = ['b_s', 'c_s', 'delta_s', 's_1', 's_2', 'NK', 's', 's_own', 'blocker'];
      steps.forEach((step) => {
        if (ancestor(step, 'sample') > 0) return;
        const light = ancestor(step, 'light');
        if (step.key === 'K' && light >= 0 && this.lights[light]) {
          const L = this.lights[light];
          const lightSteps = ['K', 'KK', 'K_len', 'K_P', 'D', 'cos_alpha', 'contribution'];
          add(this.segment(p, L, quantityColour('K'), true), lightSteps.map((k) => `${light}:${k}`), 'K',
            p.clone().lerp(L, 0.5), quantityColour('K'),
            { kind: 'K', light, text: t('page_draw_K', { light: lightName(light) }), points: { from: p, to: L } });
        }
        if (step.key === 'blocker' && light >= 0 && this.lights[light]) {
          const L = this.lights[light];
          const keys = shadowKeys.map((k) => `${light}:${k}`);
          const colour = quantityColour('blocker');
          const match = /^(sphere|plane) (\d+)$/.exec(String(step.value_full));
          // The blocker's own test inside this light's block: where it meets the ray.
          let s = null;
          let sStep = null;
          if (match)
            for (const other of steps) {
              if (ancestor(other, 'light') !== light || ancestor(other, match[1]) !== Number(match[2])) continue;
              if (!['s_1', 's_2', 's'].includes(other.key)) continue;
              const value = numberOf(other.value_full);
              if (value > 0 && value < 1 && (s === null || value < s)) {
                s = value;
                sStep = other;
              }
            }
          if (match && s !== null) {
            const hit = p.clone().lerp(L, s); // P + sK
            add(this.dashed(p, hit, colour), keys, null, null, colour);
            add(this.dashed(hit, L, '#bbbbbb'), keys, null, null, '#bbbbbb');
            const cross = new Mesh(new SphereGeometry(0.045, 12, 8), new MeshBasicMaterial({ color: 0xd55e00, transparent: true }));
            cross.position.copy(hit);
            const symbol = sStep.key === 's' ? 's' : sStep.key === 's_1' ? 's₁' : 's₂';
            add(cross, keys, `P + ${symbol}K`, hit, '#D55E00', {
              kind: 'shadow', light, symbol: t('page_draw_shadow_symbol'),
              text: t('page_draw_shadow_blocked', {
                light: lightName(light), blocker: shownOf(step).value_shown, s: `${symbol} = ${shownOf(sStep).value_shown}`,
              }),
              points: { from: p, to: L, hit }, data: { result: 'blocked', s: sStep.value_full, blocker: step.value_full },
            });
            const object = this.objects[match[1]][Number(match[2])];
            if (object) {
              const outline = new LineSegments(new EdgesGeometry(object.geometry), new LineBasicMaterial({ color: 0xd55e00, transparent: true }));
              outline.position.copy(object.position);
              outline.quaternion.copy(object.quaternion);
              add(outline, keys, null, null, '#D55E00');
            }
          } else {
            add(this.dashed(p, L, colour), keys, t('page_draw_shadow_free_label'), p.clone().lerp(L, 0.3), colour, {
              kind: 'shadow', light, symbol: t('page_draw_shadow_symbol'),
              text: t('page_draw_shadow_free', { light: lightName(light) }),
              points: { from: p, to: L }, data: { result: 'free' },
            });
          }
        }
        if ((step.key === 'R_hat' || step.key === 'R') && light >= 0) {
          const R = vec(step);
          if (R) {
            const tip = p.clone().add(toThree(R).normalize().multiplyScalar(0.7));
            add(this.segment(p, tip, quantityColour('R_hat'), true), [`${light}:${step.key}`], 'R', tip, quantityColour('R_hat'),
              { kind: 'R', light, text: t('page_draw_R', { light: lightName(light) }), points: { from: p, to: tip } });
          }
        }
      });
    }
    this.render();
  }

  // Draws the current step's quantity bold and the others faint.
  setStep(step, view) {
    const groups = (view && view.groups) || [];
    let light = groups.some((g) => g.kind === 'light') ? -1 : 0;
    if (step) for (let g = step.group; g >= 0 && g < groups.length; g = groups[g].parent) if (groups[g].kind === 'light') { light = groups[g].index; break; }
    const key = step ? step.key : null;
    for (const mark of this.marks) {
      const current = key !== null && (mark.keys.includes(key) || mark.keys.includes(`${light}:${key}`));
      mark.current = current;
      mark.object.traverse((o) => {
        if (o.material) o.material.opacity = current ? 1 : 0.35;
      });
      mark.object.scale.setScalar(1);
      if (current && mark.object.children.length) mark.object.children.forEach((c) => c.scale.set(2.2, 1, 2.2));
      else mark.object.children.forEach((c) => c.scale.set(1, 1, 1));
    }
    this.render();
  }

  // Asks for a drawing: at most one a frame, however many changes ask.
  render() {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => this.flush());
  }

  // Draws now what was asked for (the page's deferred drawing, the tests).
  // A view not laid out (its panel hidden) is not drawn: its ResizeObserver
  // asks again when it gets a size.
  flush() {
    if (!this.frame) return;
    cancelAnimationFrame(this.frame);
    this.frame = 0;
    if (!this.available || !this.canvas.isConnected || this.canvas.getClientRects().length === 0) return;
    const width = this.canvas.clientWidth || 400;
    const height = this.canvas.clientHeight || 300;
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setSize(width, height, false);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    const { theta, phi, radius, target } = this.orbit;
    this.camera.position.set(target.x + radius * Math.sin(phi) * Math.sin(theta), target.y + radius * Math.cos(phi),
      target.z + radius * Math.sin(phi) * Math.cos(theta));
    this.camera.lookAt(target);
    timed('view3d', () => {
      this.renderer.render(this.scene, this.camera);
      this.drawLabels(width, height);
    });
  }

  // The symbols as HTML text over the canvas (textContent: never markup).
  drawLabels(width, height) {
    const items = [...(this.fixedLabels || []), ...this.marks.filter((m) => m.label).map((m) => ({
      text: m.label, at: m.at, colour: m.colour, current: m.current,
    }))];
    this.labels.replaceChildren();
    for (const item of items) {
      const v = item.at.clone().project(this.camera);
      if (v.z > 1) continue;
      const label = document.createElement('span');
      label.className = item.current ? 'label current' : 'label';
      label.textContent = item.text;
      label.style.color = item.colour;
      label.style.left = `${((v.x + 1) / 2) * width}px`;
      label.style.top = `${((1 - v.y) / 2) * height}px`;
      this.labels.append(label);
    }
  }
}
