// One of the (at most two) views: the mesh, the decal of the current map
// textured in (u, v), its flipped triangles in red and the source marker,
// in a scene of its own; the views share the mesh's geometry and the camera.

import * as THREE from 'three';

// A checkerboard of yellow and blue squares (colours no lit grey surface
// has, so that a test can find the decal in a screenshot).
export function checkerTexture() {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = 64;
  const g = canvas.getContext('2d');
  for (let i = 0; i < 2; ++i)
    for (let j = 0; j < 2; ++j) {
      g.fillStyle = (i + j) % 2 ? '#2850c8' : '#f0c828';
      g.fillRect(32 * i, 32 * j, 32, 32);
    }
  const texture = new THREE.CanvasTexture(canvas);
  texture.wrapS = texture.wrapT = THREE.RepeatWrapping;
  texture.magFilter = THREE.NearestFilter;
  texture.colorSpace = THREE.SRGBColorSpace;
  return texture;
}

export class ViewPane {
  // `base`: the mesh's BufferGeometry (positions, normals, index); `faces`:
  // its corners, three per face; `markerSize` in mesh units.
  constructor(base, faces, markerSize) {
    this.faces = faces;
    this.vertexCount = base.getAttribute('position').count;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x1d2025);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 1.6));
    const light = new THREE.DirectionalLight(0xffffff, 1.4);
    light.position.set(1, 2, 3);
    this.scene.add(light);
    this.surface = new THREE.Mesh(base, new THREE.MeshLambertMaterial({ color: 0xb4b4b4 }));
    this.scene.add(this.surface);

    // The decal: the mesh's positions and normals with (u, v) as texture
    // coordinates, drawn for the patch's faces only, in front of the mesh.
    this.uv = new THREE.BufferAttribute(new Float32Array(2 * this.vertexCount), 2);
    this.uv.setUsage(THREE.DynamicDrawUsage);
    const decal = new THREE.BufferGeometry();
    decal.setAttribute('position', base.getAttribute('position'));
    decal.setAttribute('normal', base.getAttribute('normal'));
    decal.setAttribute('uv', this.uv);
    this.decalMaterial = new THREE.MeshLambertMaterial({
      map: checkerTexture(), polygonOffset: true, polygonOffsetFactor: -1, polygonOffsetUnits: -1,
    });
    this.decal = new THREE.Mesh(decal, this.decalMaterial);
    this.decal.visible = false;
    this.scene.add(this.decal);

    const flipped = new THREE.BufferGeometry();
    flipped.setAttribute('position', base.getAttribute('position'));
    this.flipped = new THREE.Mesh(flipped, new THREE.MeshBasicMaterial({
      color: 0xdc1e1e, side: THREE.DoubleSide, polygonOffset: true, polygonOffsetFactor: -2,
      polygonOffsetUnits: -2,
    }));
    this.flipped.visible = false;
    this.scene.add(this.flipped);

    this.marker = new THREE.Mesh(new THREE.SphereGeometry(markerSize, 16, 12),
      new THREE.MeshBasicMaterial({ color: 0xffffff }));
    this.marker.visible = false;
    this.scene.add(this.marker);

    this.position = new Int32Array(this.vertexCount).fill(-1);  // vertex -> place in the map
    this.imageMode = false;
    this.scale = null;  // mesh units per texture repeat; kept while dragging
    this.mapsDrawn = 0;
    this.lastMap = null;
    this.drawTimes = [];
  }

  // Use `texture` (an image the user dropped) stretched over the patch
  // instead of the checkerboard; null goes back to the checkerboard.
  setImage(texture) {
    this.imageMode = Boolean(texture);
    this.decalMaterial.map = texture || checkerTexture();
    this.decalMaterial.needsUpdate = true;
    if (this.lastMap) this.show(this.lastMap);
  }

  // A new patch setting: the texture's scale follows the next map.
  resetScale() { this.scale = null; }

  show(map) {
    const n = map.vertices.length;
    let rMax = 0;
    for (let i = 0; i < n; ++i) rMax = Math.max(rMax, map.r[i]);
    if (!this.scale) this.scale = rMax > 0 ? rMax : 1;
    // The checkerboard: 8 squares across the patch's diameter. An image:
    // the patch's disk inscribed in it.
    const uv = this.uv.array;
    for (const v of this.lastMap ? this.lastMap.vertices : []) this.position[v] = -1;
    for (let i = 0; i < n; ++i) {
      const v = map.vertices[i];
      this.position[v] = i;
      if (this.imageMode) {
        uv[2 * v] = 0.5 + map.u[i] / (2 * this.scale);
        uv[2 * v + 1] = 0.5 + map.v[i] / (2 * this.scale);
      } else {
        uv[2 * v] = map.u[i] / (this.scale / 4) / 2;
        uv[2 * v + 1] = map.v[i] / (this.scale / 4) / 2;
      }
    }
    this.uv.needsUpdate = true;

    const faces = this.faces, patch = [];
    for (let f = 0; f < faces.length; f += 3)
      if (this.position[faces[f]] >= 0 && this.position[faces[f + 1]] >= 0 && this.position[faces[f + 2]] >= 0)
        patch.push(faces[f], faces[f + 1], faces[f + 2]);
    this.decal.geometry.setIndex(patch);
    this.decal.visible = true;

    const flipped = [];
    for (const f of map.flipped_faces) flipped.push(faces[3 * f], faces[3 * f + 1], faces[3 * f + 2]);
    this.flipped.geometry.setIndex(flipped);
    this.flipped.visible = flipped.length > 0;

    this.marker.position.fromArray(map.source.position);
    this.marker.visible = true;
    this.lastMap = map;
    this.mapsDrawn += 1;
    const now = performance.now();
    this.drawTimes.push(now);
    while (this.drawTimes.length > 1 && now - this.drawTimes[0] > 2000) this.drawTimes.shift();
  }

  // Maps drawn per second over the last two seconds (while dragging).
  rate() {
    const t = this.drawTimes;
    if (t.length < 3 || performance.now() - t[t.length - 1] > 1000) return null;
    return (t.length - 1) / ((t[t.length - 1] - t[0]) / 1000);
  }

  clear() {
    this.decal.visible = this.flipped.visible = this.marker.visible = false;
    if (this.lastMap) for (const v of this.lastMap.vertices) this.position[v] = -1;
    this.lastMap = null;
  }
}
