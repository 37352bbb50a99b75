#include "preview_page_3d.hpp"

#include "three_js.hpp"

namespace fapc::face {

namespace {

// Plays the page's glTF: the glTF's own animation (a mixer held at the shown frame's time) sets
// the morph weights and the head's and eyes' rotations. The weights are applied here, on the CPU,
// rather than by three.js's shader: r111's shader adds at most 8 targets at once and a talking face
// moves more. The camera looks at the neutral head from the front; the mouse orbits it.
constexpr std::string_view kScript = R"JS(
window.fapcHead3d = (function () {
  const canvas = document.getElementById('head3d');
  const text = atob(document.getElementById('head-glb').textContent);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  const renderer = new THREE.WebGLRenderer({canvas: canvas, antialias: true, preserveDrawingBuffer: true});
  renderer.setPixelRatio(1);
  renderer.setSize(canvas.width, canvas.height, false);
  renderer.setClearColor(0x46505a);
  renderer.gammaOutput = true;
  renderer.gammaFactor = 2.2;
  const scene = new THREE.Scene();
  scene.add(new THREE.HemisphereLight(0xffffff, 0x505050, 0.9));
  const sun = new THREE.DirectionalLight(0xffffff, 0.8);
  sun.position.set(0.3, 0.6, 1);
  scene.add(sun);
  const fov = 24;
  const camera = new THREE.PerspectiveCamera(fov, canvas.width / canvas.height, 0.01, 10);
  const state = {ready: false, time: 0, action: null, mixer: null, blends: [], weights: null, draws: 0, scene: null, mesh: null};
  function blend() {
    for (const b of state.blends) {
      const out = b.position.array;
      out.set(b.base);
      state.weights.forEach((w, i) => {
        if (w === 0) return;
        const d = b.morphs[i];
        for (let j = 0; j < out.length; ++j) out[j] += w * d[j];
      });
      b.position.needsUpdate = true;
    }
  }
  function draw() {
    if (!state.ready) return;
    renderer.render(scene, camera);
    state.draws++;
  }
  function show(t) {
    state.time = t;
    if (!state.ready) return;
    if (state.action) {
      state.action.enabled = true;
      state.action.paused = false;
      state.action.time = Math.max(0, Math.min(t, state.action.getClip().duration));
      state.mixer.update(0);
    }
    if (state.weights) blend();
    draw();
  }
  const loaded = new Promise((resolve, reject) => new THREE.GLTFLoader().parse(bytes.buffer, '', resolve, reject))
    .then(gltf => {
      scene.add(gltf.scene);
      state.scene = gltf.scene;
      const shared = new Map();
      gltf.scene.traverse(o => {
        if (!o.isMesh) return;
        o.frustumCulled = false;
        const morphs = o.geometry.morphAttributes.position;
        if (!morphs || !o.morphTargetInfluences) return;
        o.material.morphTargets = false;  // blended above instead
        o.material.needsUpdate = true;
        state.weights = o.morphTargetInfluences;
        state.mesh = o;
        const position = o.geometry.attributes.position;
        if (!shared.has(position))
          shared.set(position, {position: position, base: position.array.slice(), morphs: morphs.map(m => m.array)});
      });
      state.blends = Array.from(shared.values());
      // The neutral head's box (Box3.setFromObject would count each target at full weight).
      gltf.scene.updateMatrixWorld(true);
      const box = new THREE.Box3();
      gltf.scene.traverse(o => {
        if (o.isMesh) box.union(new THREE.Box3().setFromBufferAttribute(o.geometry.attributes.position).applyMatrix4(o.matrixWorld));
      });
      const centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
      const half = Math.max(size.y, size.x / camera.aspect) / 2 * 1.25;  // room for the jaw
      camera.position.set(centre.x, centre.y, box.max.z + half / Math.tan(fov / 2 * Math.PI / 180));
      camera.lookAt(centre);
      document.body.dataset.camera3d = JSON.stringify({fov: fov, aspect: camera.aspect,
        position: camera.position.toArray(), target: centre.toArray()});
      if (gltf.animations.length) {
        state.mixer = new THREE.AnimationMixer(gltf.scene);
        state.action = state.mixer.clipAction(gltf.animations[0]);
        state.action.setLoop(THREE.LoopOnce);
        state.action.clampWhenFinished = true;
        state.action.play();
      }
      const controls = new THREE.OrbitControls(camera, canvas);
      controls.target.copy(centre);
      controls.update();
      controls.addEventListener('change', draw);
      state.ready = true;
      show(state.time);
    })
    .catch(e => { document.body.dataset.head3dError = String(e); throw e; });
  // What is shown, for tests: the nodes' rotations (x, y, z, w) and the weights by target name.
  function pose() {
    const rotation = name => state.scene.getObjectByName(name).quaternion.toArray();
    const weights = {};
    for (const name in state.mesh.morphTargetDictionary) weights[name] = state.weights[state.mesh.morphTargetDictionary[name]];
    return {head: rotation('head'), eye_l: rotation('eye_l'), eye_r: rotation('eye_r'), weights: weights};
  }
  return {loaded: loaded, show: show, draws: () => state.draws, pose: pose};
})();
)JS";

}  // namespace

int head3d_left(const PreviewOptions& o) { return o.view == PreviewView::both ? o.width : 0; }

std::string head3d_view(const PreviewOptions& o) {
  std::string html = "<canvas id=\"head3d\" width=\"" + std::to_string(o.width) + "\" height=\"" +
                     std::to_string(o.height) + "\"></canvas>\n<!--\n";
  html += kThreeJsLicence;
  html += "-->\n";
  for (const ScriptFile& file : three_js_sources()) {
    html += "<script>/* ";
    html += file.name;
    html += " */\n";
    html += file.text;
    html += "\n</script>\n";
  }
  html += "<script id=\"head-glb\" type=\"application/octet-stream\">";
  html += base64(o.head_glb);
  html += "</script>\n<script>";
  html += kScript;
  html += "</script>\n";
  return html;
}

}  // namespace fapc::face
