// The browser view of the plant's world, as gzclient shows it: the scene the node publishes on
// /gazebo/scene (every visual of the world and of each robot's links with its material, the world's
// lights, the ambient light and the background), lit as the plant's cameras light it, its links
// posed live from /gazebo/link_states, orbit / pan / zoom. The viewer node (scripts/viewer) sends
// both over one WebSocket and serves the meshes' files.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { ColladaLoader } from 'three/examples/jsm/loaders/ColladaLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { MTLLoader } from 'three/examples/jsm/loaders/MTLLoader.js';

// ROS and Gazebo are z up.
THREE.Object3D.DEFAULT_UP.set(0, 0, 1);
// Colours as the plant's cameras shade them: no colour-space conversion.
THREE.ColorManagement.enabled = false;

const GROUND_SIZE = 200;  // m: a plane is infinite; this much of it is drawn

const canvas = document.getElementById('view');
// No multisampling: SwiftShader (a browser without a GPU) draws the mesh track at 30 fps without it, not with it.
const renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
renderer.setPixelRatio(window.devicePixelRatio);
const scene = new THREE.Scene();
const camera = new THREE.PerspectiveCamera(60, 1, 0.01, 1000);
camera.position.set(-3, -3, 4);
const controls = new OrbitControls(camera, canvas);
controls.target.set(0, 0, 0);
controls.update();

// A frame is drawn when what it shows changed (the scene, poses, an overlay, a mesh loaded, the view
// moved or resized), not at every animation frame: without a GPU the browser draws on the CPU
// (SwiftShader), and a paused world then costs nothing to show. Poses come at the plant's
// ~scene_rate (30 a simulated second), so a running world is drawn at that rate.
let redrawWanted = true;
function redraw() {
  redrawWanted = true;
}
controls.addEventListener('change', redraw);


// World visuals (posed once) and robot links (posed by link_states), by link name.
const world = new THREE.Group();
scene.add(world);
const links = new Map();
const linkPoses = new Map();  // every link of link_states, drawn or not
let pendingMeshes = 0;
let posesReceived = 0;
let simTime = 0;

function resize() {
  const width = canvas.clientWidth, height = canvas.clientHeight;
  if (canvas.width !== Math.floor(width * renderer.getPixelRatio()) ||
      canvas.height !== Math.floor(height * renderer.getPixelRatio())) {
    renderer.setSize(width, height, false);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    redraw();
  }
}

function setPose(object, pose) {
  object.position.set(pose[0], pose[1], pose[2]);
  object.quaternion.set(pose[3], pose[4], pose[5], pose[6]);
}

// The plant's cameras' lighting (pinhole.h: OGRE's per-pixel lighting as Gazebo 11 draws it), per
// pixel on the face the view sees: emissive + scene ambient x material ambient + each light's diffuse
// x material diffuse x n . l (times the texture) + its specular x material specular x (n . h)^shininess
// where the material has specular, a point or spot light attenuated by 1 / (constant + linear d +
// quadratic d^2) within its range, a spot by its cone. The first 8 lights of the world (OGRE's limit
// on one object; the cameras take each object's 8 nearest); no shadows.
const MAX_LIGHTS = 8;
const lighting = {
  sceneAmbient: { value: new THREE.Vector3(0.4, 0.4, 0.4) },
  lightCount: { value: 0 },
  lightPosition: { value: Array.from({ length: MAX_LIGHTS }, () => new THREE.Vector4()) },  // w: 0 directional, 1 point, 2 spot
  lightDirection: { value: Array.from({ length: MAX_LIGHTS }, () => new THREE.Vector3()) },
  lightDiffuse: { value: Array.from({ length: MAX_LIGHTS }, () => new THREE.Vector3()) },
  lightSpecular: { value: Array.from({ length: MAX_LIGHTS }, () => new THREE.Vector3()) },
  lightAttenuation: { value: Array.from({ length: MAX_LIGHTS }, () => new THREE.Vector4()) },
  lightSpot: { value: Array.from({ length: MAX_LIGHTS }, () => new THREE.Vector3()) },
};

const VERTEX_SHADER = `
varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec2 textureUv;
void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  worldPosition = world.xyz;
  worldNormal = transpose(inverse(mat3(modelMatrix))) * normal;
  textureUv = uv;
  gl_Position = projectionMatrix * viewMatrix * world;
}
`;

const FRAGMENT_SHADER = `
uniform vec3 sceneAmbient;
uniform int lightCount;
uniform vec4 lightPosition[${MAX_LIGHTS}];
uniform vec3 lightDirection[${MAX_LIGHTS}];
uniform vec3 lightDiffuse[${MAX_LIGHTS}];
uniform vec3 lightSpecular[${MAX_LIGHTS}];
uniform vec4 lightAttenuation[${MAX_LIGHTS}];
uniform vec3 lightSpot[${MAX_LIGHTS}];
uniform vec3 materialAmbient;
uniform vec4 materialDiffuse;
uniform vec3 materialSpecular;
uniform vec3 materialEmissive;
uniform float shininess;
uniform sampler2D image;
varying vec3 worldPosition;
varying vec3 worldNormal;
varying vec2 textureUv;
void main() {
  vec3 n = normalize(worldNormal) * (gl_FrontFacing ? 1.0 : -1.0);
  vec3 toEye = normalize(cameraPosition - worldPosition);
  vec3 diffuse = vec3(0.0), specular = vec3(0.0);
  for (int i = 0; i < ${MAX_LIGHTS}; ++i) {
    if (i >= lightCount) break;
    vec3 l;
    float share = 1.0;
    if (lightPosition[i].w == 0.0) {
      l = -lightDirection[i];
    } else {
      vec3 toLight = lightPosition[i].xyz - worldPosition;
      float d = length(toLight);
      l = toLight / max(d, 1e-20);
      vec4 a = lightAttenuation[i];
      share = d <= a.x ? 1.0 / (a.y + a.z * d + a.w * d * d) : 0.0;
      if (lightPosition[i].w == 2.0) {
        float rho = dot(-l, lightDirection[i]);
        float inner = lightSpot[i].x, outer = lightSpot[i].y;
        float spot = rho < outer ? 0.0 : inner > outer ? clamp((rho - outer) / (inner - outer), 0.0, 1.0) : 1.0;
        share *= lightSpot[i].z > 0.0 ? pow(spot, lightSpot[i].z) : step(outer, rho);
      }
    }
    float nl = dot(n, l);
    if (nl > 0.0) {
      diffuse += lightDiffuse[i] * nl * share;
#if SPECULAR
      specular += lightSpecular[i] * pow(max(0.0, dot(n, normalize(l + toEye))), shininess) * share;
#endif
    }
  }
#if TEXTURED
  vec4 texel = texture2D(image, textureUv);
#else
  vec4 texel = vec4(1.0);
#endif
  vec3 lit = (materialEmissive + sceneAmbient * materialAmbient + materialDiffuse.rgb * diffuse) * texel.rgb +
             materialSpecular * specular;
  gl_FragColor = vec4(clamp(lit, 0.0, 1.0), materialDiffuse.a * texel.a);
}
`;

const vector3 = (c) => new THREE.Vector3(c[0], c[1], c[2]);
// The world's lights as buildScene found them: the largest specular light a surface can meet (a
// specular share below a level is left out, as the cameras leave it), and whether all are directional.
const worldLights = { strongestSpecular: 0, allDirectional: true, list: [] };

// A material of the scene's JSON ({ambient, diffuse, specular, emissive: [r g b a], shininess}), a
// texture's image over its ambient and diffuse light where `map` is given.
function material(m, map = null) {
  const specular = m.shininess > 0 && Math.max(m.specular[0], m.specular[1], m.specular[2]) *
    worldLights.strongestSpecular >= 1 / 255;
  const opacity = m.diffuse[3];
  return new THREE.ShaderMaterial({
    uniforms: {
      ...lighting,
      materialAmbient: { value: vector3(m.ambient) },
      materialDiffuse: { value: new THREE.Vector4(m.diffuse[0], m.diffuse[1], m.diffuse[2], opacity) },
      materialSpecular: { value: vector3(m.specular) },
      materialEmissive: { value: vector3(m.emissive) },
      shininess: { value: m.shininess },
      image: { value: map },
    },
    defines: { TEXTURED: map ? 1 : 0, SPECULAR: specular ? 1 : 0 },
    userData: { plant: m, map },
    vertexShader: VERTEX_SHADER,
    fragmentShader: FRAGMENT_SHADER,
    side: THREE.DoubleSide,
    transparent: opacity < 1,
    depthWrite: opacity >= 1,
  });
}

// What the plant's cameras see on a mesh file's sub-mesh: its own material (by name) as the plant
// applied the visual's to it, with the loader's texture where the plant draws one; the visual's
// material (on Gazebo's white) where the file names none the plant knows.
function meshMaterial(visual, loaded) {
  const own = (visual.mesh_materials || []).find((m) => m.name === loaded.name);
  if (own) return material(own.material, own.textured && loaded.map ? loaded.map : null);
  return material(visual.material);
}

// The world's visuals never move: where every light is directional and a surface has no specular
// share, its light at each vertex is all there is to it (exact on flat faces: n . l is the same
// over a face; Gouraud on curved ones), worked out once into vertex colours of an unlit material
// (SwiftShader, a browser without a GPU, draws the mesh race track about a third faster so). A face
// seen from behind keeps its front's shade.
function bakeLighting(object) {
  if (!worldLights.allDirectional) return;
  object.updateWorldMatrix(true, true);
  object.traverse((child) => {
    if (!child.isMesh || child.userData.baked) return;
    const materials = Array.isArray(child.material) ? child.material : [child.material];
    if (materials.some((m) => !m.isShaderMaterial || m.defines.SPECULAR) || materials.length > 1) return;
    const { plant: m, map } = materials[0].userData;
    const geometry = child.geometry.clone();  // a loader may share one geometry between meshes
    if (!geometry.getAttribute('normal')) geometry.computeVertexNormals();
    const normals = geometry.getAttribute('normal');
    const toWorld = new THREE.Matrix3().getNormalMatrix(child.matrixWorld);
    const n = new THREE.Vector3(), shades = new Float32Array(normals.count * 3);
    const ambient = lighting.sceneAmbient.value;
    const base = [m.emissive[0] + ambient.x * m.ambient[0], m.emissive[1] + ambient.y * m.ambient[1],
                  m.emissive[2] + ambient.z * m.ambient[2]];
    for (let k = 0; k < normals.count; k++) {
      n.fromBufferAttribute(normals, k).applyMatrix3(toWorld).normalize();
      const light = [0, 0, 0];
      for (const l of worldLights.list) {
        const nl = -(n.x * l.direction[0] + n.y * l.direction[1] + n.z * l.direction[2]);
        if (nl > 0) for (let c = 0; c < 3; c++) light[c] += l.diffuse[c] * nl;
      }
      for (let c = 0; c < 3; c++) shades[3 * k + c] = Math.min(1, base[c] + m.diffuse[c] * light[c]);
    }
    geometry.setAttribute('color', new THREE.BufferAttribute(shades, 3));
    child.geometry = geometry;
    child.material = new THREE.MeshBasicMaterial({
      map, vertexColors: true, side: THREE.DoubleSide, transparent: m.diffuse[3] < 1, opacity: m.diffuse[3],
      depthWrite: m.diffuse[3] >= 1,
    });
    child.userData.baked = true;
  });
}

function fileUrl(path) {
  return '/files' + path.split('/').map(encodeURIComponent).join('/');
}

// A mesh file through three.js's loader for its kind; what it holds goes into `into`, scaled.
function loadMesh(visual, into) {
  const url = fileUrl(visual.mesh);
  const extension = visual.mesh.split('.').pop().toLowerCase();
  const scale = visual.scale || [1, 1, 1];
  const done = (object) => {
    // As the plant's cameras draw them: both sides lit, normals from the faces where a file has none,
    // each sub-mesh in the material the plant gives it.
    object.traverse((child) => {
      if (!child.isMesh) return;
      if (!child.geometry.getAttribute('normal')) child.geometry.computeVertexNormals();
      if (!child.geometry.getAttribute('uv')) {
        child.geometry.setAttribute('uv', new THREE.BufferAttribute(new Float32Array(2 * child.geometry.getAttribute('position').count), 2));
      }
      child.material = Array.isArray(child.material) ? child.material.map((m) => meshMaterial(visual, m))
        : meshMaterial(visual, child.material);
    });
    const scaled = new THREE.Group();
    scaled.scale.set(scale[0], scale[1], scale[2]);
    scaled.add(object);
    into.add(scaled);
    if (into.parent === world) bakeLighting(into);
    pendingMeshes -= 1;
    redraw();
  };
  const failed = (error) => {
    console.error('viewer: mesh ' + visual.mesh + ': ' + error);
    pendingMeshes -= 1;
  };
  pendingMeshes += 1;
  if (extension === 'stl') {
    new STLLoader().load(url, (geometry) => {
      geometry.computeVertexNormals();
      done(new THREE.Mesh(geometry, material(visual.material)));
    }, undefined, failed);
  } else if (extension === 'dae') {
    new ColladaLoader().load(url, (collada) => {
      // The loader turns the file y up (its <up_axis> and <unit> applied to its scene); Gazebo and
      // the plant then take y up to z up (mesh_loader.cpp): a file written z up stands as written.
      const zUp = new THREE.Group();
      zUp.rotation.x = Math.PI / 2;
      zUp.add(collada.scene);
      done(zUp);
    }, undefined, failed);
  } else if (extension === 'obj') {
    const directory = url.substring(0, url.lastIndexOf('/') + 1);
    fetch(url).then((response) => response.text()).then((text) => {
      const library = /^mtllib\s+(.+)$/m.exec(text);
      const withMaterials = (materials) => {
        const loader = new OBJLoader();
        if (materials) {
          materials.preload();
          loader.setMaterials(materials);
        }
        done(loader.parse(text));
      };
      if (library) {
        new MTLLoader().setPath(directory).load(library[1].trim(), withMaterials, undefined, () => withMaterials(null));
      } else {
        withMaterials(null);
      }
    }).catch(failed);
  } else {
    failed('not a mesh kind the viewer loads (STL, Collada, OBJ)');
  }
}

function shapeOf(visual) {
  if (visual.kind === 'box') {
    const s = visual.size;
    return new THREE.Mesh(new THREE.BoxGeometry(s[0], s[1], s[2]), material(visual.material));
  }
  if (visual.kind === 'sphere') {
    return new THREE.Mesh(new THREE.SphereGeometry(visual.radius, 32, 16), material(visual.material));
  }
  if (visual.kind === 'cylinder') {
    const mesh = new THREE.Mesh(new THREE.CylinderGeometry(visual.radius, visual.radius, visual.length, 32),
                                material(visual.material));
    mesh.rotation.x = Math.PI / 2;  // three.js's cylinders lie along y, URDF's and SDF's along z
    const holder = new THREE.Group();
    holder.add(mesh);
    return holder;
  }
  if (visual.kind === 'capsule') {
    const mesh = new THREE.Mesh(new THREE.CapsuleGeometry(visual.radius, visual.length, 8, 32),
                                material(visual.material));
    mesh.rotation.x = Math.PI / 2;  // along y in three.js, along z in SDF
    const holder = new THREE.Group();
    holder.add(mesh);
    return holder;
  }
  if (visual.kind === 'ellipsoid') {
    const mesh = new THREE.Mesh(new THREE.SphereGeometry(1, 32, 16), material(visual.material));
    mesh.scale.set(visual.radii[0], visual.radii[1], visual.radii[2]);
    return mesh;
  }
  if (visual.kind === 'plane') {
    const mesh = new THREE.Mesh(new THREE.PlaneGeometry(GROUND_SIZE, GROUND_SIZE), material(visual.material));
    const n = visual.normal;
    mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), new THREE.Vector3(n[0], n[1], n[2]).normalize());
    return mesh;
  }
  return null;
}

function buildScene(description) {
  world.clear();
  for (const link of links.values()) scene.remove(link);
  links.clear();
  const background = description.background;
  scene.background = new THREE.Color(background[0], background[1], background[2]);
  lighting.sceneAmbient.value.set(...description.ambient);
  const lights = description.lights.slice(0, MAX_LIGHTS);
  lighting.lightCount.value = lights.length;
  const kinds = { directional: 0, point: 1, spot: 2 };
  worldLights.list = lights;
  worldLights.allDirectional = lights.every((light) => light.type === 'directional');
  worldLights.strongestSpecular = Math.max(0, ...lights.map((light) => Math.max(...light.specular) *
    (light.type === 'directional' ? 1 : 1 / Math.max(light.attenuation[1], 1e-3))));
  lights.forEach((light, k) => {
    lighting.lightPosition.value[k].set(...light.position, kinds[light.type]);
    lighting.lightDirection.value[k].set(...light.direction);
    lighting.lightDiffuse.value[k].set(...light.diffuse);
    lighting.lightSpecular.value[k].set(...light.specular);
    lighting.lightAttenuation.value[k].set(...light.attenuation);
    lighting.lightSpot.value[k].set(Math.cos(light.spot[0] / 2), Math.cos(light.spot[1] / 2), light.spot[2]);
  });
  for (const visual of description.visuals) {
    const holder = new THREE.Group();
    setPose(holder, visual.pose);
    if (visual.kind === 'mesh') {
      loadMesh(visual, holder);
    } else {
      holder.add(shapeOf(visual));
    }
    if (visual.model === '') {
      world.add(holder);
      bakeLighting(holder);
    } else {
      if (!links.has(visual.link)) {
        const link = new THREE.Group();
        link.name = visual.link;
        link.visible = false;  // until link_states places it
        links.set(visual.link, link);
        scene.add(link);
      }
      links.get(visual.link).add(holder);
    }
  }
  rootLinks.clear();
  description.robots.forEach((robot, k) => rootLinks.set(robot, description.root_links[k]));
  listModels(description.robots);
  document.getElementById('world').textContent = description.world;
}

// The model list: each robot's pose (its root link's: x, y, yaw), follow, move.
const rootLinks = new Map();  // robot: its root link, model::link
let following = null, followedAt = null;
let moving = null;  // the robot the next drag moves (shift: turns)

function listModels(robots) {
  const list = document.getElementById('models');
  list.innerHTML = robots.length ? '' : 'no robots';
  if (!robots.includes(following)) following = null;
  if (!robots.includes(moving)) moving = null;
  for (const robot of robots) {
    const row = document.createElement('div');
    row.className = 'model';
    row.dataset.model = robot;
    const follow = document.createElement('input');
    follow.type = 'checkbox';
    follow.className = 'follow';
    follow.checked = following === robot;
    follow.onchange = () => {
      for (const other of list.querySelectorAll('input.follow')) if (other !== follow) other.checked = false;
      following = follow.checked ? robot : null;
      // followed from where it is drawn now: the next poses may already have it elsewhere (a
      // set_model_state right after the tick), a move the camera must follow too
      const drawn = following && linkPoses.get(rootLinks.get(following));
      followedAt = drawn ? new THREE.Vector3(drawn[0], drawn[1], drawn[2]) : null;
    };
    const move = document.createElement('button');
    move.className = 'move';
    move.textContent = 'move';
    move.title = 'then drag in the view to move it, shift-drag to turn it (set_model_state)';
    move.onclick = () => {
      moving = moving === robot ? null : robot;
      for (const b of list.querySelectorAll('button.move')) {
        b.classList.toggle('moving', b === move && moving === robot);
      }
    };
    const label = document.createElement('label');
    label.append(follow, ' follow ');
    row.append(Object.assign(document.createElement('b'), { textContent: robot }), ' ',
               Object.assign(document.createElement('span'), { className: 'pose' }), ' ', label, move);
    list.appendChild(row);
  }
}

function yawOf(pose) {
  const [x, y, z, w] = pose.slice(3);
  return Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
}

function showModelPoses() {
  for (const row of document.querySelectorAll('#models .model')) {
    const pose = linkPoses.get(rootLinks.get(row.dataset.model));
    if (pose) {
      row.querySelector('.pose').textContent = 'x ' + pose[0].toFixed(2) + ' y ' + pose[1].toFixed(2) +
        ' yaw ' + (yawOf(pose) * 180 / Math.PI).toFixed(0) + '\u00b0';
    }
  }
  const pose = following && linkPoses.get(rootLinks.get(following));
  if (pose) {
    const at = new THREE.Vector3(pose[0], pose[1], pose[2]);
    if (followedAt) {
      const step = at.clone().sub(followedAt);
      camera.position.add(step);
      controls.target.add(step);
    }
    followedAt = at;
  }
}

// Dragging a model in move mode: where the pointer meets the horizontal plane at the model's height.
const raycaster = new THREE.Raycaster();
let drag = null;

function groundPoint(event, height) {
  const rect = canvas.getBoundingClientRect();
  const ndc = new THREE.Vector2((event.clientX - rect.left) / rect.width * 2 - 1,
                                -(event.clientY - rect.top) / rect.height * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  const at = new THREE.Vector3();
  return raycaster.ray.intersectPlane(new THREE.Plane(new THREE.Vector3(0, 0, 1), -height), at) ? at : null;
}

canvas.addEventListener('pointerdown', (event) => {
  const pose = moving && linkPoses.get(rootLinks.get(moving));
  if (!pose || event.button !== 0) return;
  const start = groundPoint(event, pose[2]);
  if (!start) return;
  drag = { model: moving, pose, start, x: event.clientX, turn: event.shiftKey };
  controls.enabled = false;
}, true);

window.addEventListener('pointerup', (event) => {
  if (!drag) return;
  controls.enabled = true;
  const { model, pose, start, x, turn } = drag;
  drag = null;
  let target = pose.slice();
  if (turn) {  // a degree a pixel across, about z
    const yaw = yawOf(pose) + (event.clientX - x) * Math.PI / 180;
    target = pose.slice(0, 3).concat([0, 0, Math.sin(yaw / 2), Math.cos(yaw / 2)]);
  } else {
    const end = groundPoint(event, pose[2]);
    if (!end) return;
    target[0] += end.x - start.x;
    target[1] += end.y - start.y;
  }
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify({ type: 'set_pose', model, pose: target }));
});

function applyPoses(message) {
  for (const [name, pose] of Object.entries(message.links)) {
    linkPoses.set(name, pose);
    const link = links.get(name);
    if (link) {
      setPose(link, pose);
      link.visible = true;
    }
  }
  simTime = message.time;
  posesReceived += 1;
  showModelPoses();
  document.getElementById('time').textContent = simTime.toFixed(3) + ' s';
}

let status = { paused: null, real_time_factor: 0 };

// Sensor overlays: a checkbox per image, scan or contacts topic; a camera's frame in a corner, a
// scan's hit points in its link, contacts as points with their normals in the world.
const overlayFrames = new Map();
const overlayObjects = new Map();  // topic: the THREE.Object3D a scan or contacts overlay draws
const CONTACT_NORMAL_LENGTH = 0.1;  // m

function showOverlayTopics(topics) {
  const list = document.getElementById('overlay_topics');
  const names = Object.keys(topics).sort();
  if (list.dataset.topics === JSON.stringify(names)) return;
  list.dataset.topics = JSON.stringify(names);
  // the list is made again when a topic comes or goes: the ones ticked stay ticked (the viewer still
  // sends them, and a frame is drawn only while its box is ticked)
  const ticked = new Set(Array.from(list.querySelectorAll('input:checked'), (box) => box.dataset.topic));
  list.innerHTML = names.length ? '' : 'none';
  for (const topic of names) {
    const label = document.createElement('label');
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.dataset.topic = topic;
    box.checked = ticked.has(topic);
    box.onchange = () => {
      if (socket && socket.readyState === WebSocket.OPEN) {
        socket.send(JSON.stringify({ type: 'overlay', topic, on: box.checked }));
      }
      const shown = document.querySelector('#images figure[data-topic="' + topic + '"]');
      if (!box.checked && shown) shown.remove();
      if (!box.checked && overlayObjects.has(topic)) {
        overlayObjects.get(topic).removeFromParent();
        overlayObjects.delete(topic);
        redraw();
      }
    };
    label.append(box, ' ' + topic + ' ');
    list.appendChild(label);
  }
}

function overlayOn(topic) {
  const box = document.querySelector('#overlay_topics input[data-topic="' + topic + '"]');
  return box && box.checked;
}

// A scan's hits as points in the link its frame names (model::frame in link_states).
function applyScan(message) {
  if (!overlayOn(message.topic)) return;
  const frame = message.frame.split('/').pop();
  const link = Array.from(links.values()).find((l) => l.name.endsWith('::' + frame));
  if (!link) return;  // a frame no drawn link has
  const xyz = [];
  message.ranges.forEach((r, k) => {
    if (r === null) return;
    const a = message.angle_min + k * message.angle_increment;
    xyz.push(r * Math.cos(a), r * Math.sin(a), 0);
  });
  let points = overlayObjects.get(message.topic);
  if (!points) {
    points = new THREE.Points(new THREE.BufferGeometry(), new THREE.PointsMaterial({ color: 0x00c000, size: 4,
                                                                                     sizeAttenuation: false }));
    overlayObjects.set(message.topic, points);
  }
  if (points.parent !== link) link.add(points);
  points.geometry.setAttribute('position', new THREE.Float32BufferAttribute(xyz, 3));
  overlayFrames.set(message.topic, (overlayFrames.get(message.topic) || 0) + 1);
}

// Contacts in the world: each point, and its normal as a line CONTACT_NORMAL_LENGTH long.
function applyContacts(message) {
  if (!overlayOn(message.topic)) return;
  let drawn = overlayObjects.get(message.topic);
  if (!drawn) {
    drawn = new THREE.Group();
    drawn.add(new THREE.Points(new THREE.BufferGeometry(),
                               new THREE.PointsMaterial({ color: 0x0060ff, size: 6, sizeAttenuation: false })));
    drawn.add(new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0x0060ff })));
    overlayObjects.set(message.topic, drawn);
    scene.add(drawn);
  }
  const at = [], normals = [];
  for (const [x, y, z, nx, ny, nz] of message.points) {
    at.push(x, y, z);
    normals.push(x, y, z, x + nx * CONTACT_NORMAL_LENGTH, y + ny * CONTACT_NORMAL_LENGTH, z + nz * CONTACT_NORMAL_LENGTH);
  }
  drawn.children[0].geometry.setAttribute('position', new THREE.Float32BufferAttribute(at, 3));
  drawn.children[1].geometry.setAttribute('position', new THREE.Float32BufferAttribute(normals, 3));
  overlayFrames.set(message.topic, (overlayFrames.get(message.topic) || 0) + 1);
}

function applyImage(message) {
  const box = document.querySelector('#overlay_topics input[data-topic="' + message.topic + '"]');
  if (!box || !box.checked) return;
  let figure = document.querySelector('#images figure[data-topic="' + message.topic + '"]');
  if (!figure) {
    figure = document.createElement('figure');
    figure.dataset.topic = message.topic;
    figure.append(document.createElement('img'), document.createElement('figcaption'));
    document.getElementById('images').appendChild(figure);
  }
  figure.querySelector('img').src = 'data:image/jpeg;base64,' + message.jpeg;
  figure.querySelector('figcaption').textContent = message.topic + ' ' + message.width + ' x ' + message.height +
    ' at ' + message.stamp.toFixed(3) + ' s';
  overlayFrames.set(message.topic, (overlayFrames.get(message.topic) || 0) + 1);
}

function applyStatus(message) {
  status = message;
  showOverlayTopics(message.overlay_topics);
  const select = document.getElementById('drive_topic');
  const offered = Array.from(select.options).map((o) => o.value).filter((v) => v);
  if (JSON.stringify(offered) !== JSON.stringify(message.drive_topics)) {
    const chosen = select.value;
    select.innerHTML = '';
    for (const topic of message.drive_topics.length ? message.drive_topics : ['']) {
      const option = document.createElement('option');
      option.value = topic;
      option.textContent = topic || '(no command topic)';
      select.appendChild(option);
    }
    if (message.drive_topics.includes(chosen)) select.value = chosen;
  }
  simTime = message.time;
  document.getElementById('time').textContent = simTime.toFixed(3) + ' s';
  document.getElementById('rtf').textContent = message.real_time_factor.toFixed(2);
  document.getElementById('paused').textContent = message.paused ? '(paused)' : '';
}

let socket = null;

function connect() {
  socket = new WebSocket((location.protocol === 'https:' ? 'wss://' : 'ws://') + location.host + '/ws');
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.type === 'scene') buildScene(message.scene);
    else if (message.type === 'poses') applyPoses(message);
    else if (message.type === 'status') applyStatus(message);
    else if (message.type === 'keys') keys = message.keys;
    else if (message.type === 'image') applyImage(message);
    else if (message.type === 'scan') applyScan(message);
    else if (message.type === 'contacts') applyContacts(message);
    if (['scene', 'poses', 'scan', 'contacts'].includes(message.type)) redraw();
  };
  socket.onclose = () => {
    document.getElementById('status').textContent = 'disconnected; retrying';
    if (!leaving) setTimeout(connect, 1000);
  };
  socket.onopen = () => { document.getElementById('status').textContent = 'connected'; };
}

let framesDrawn = 0;

function frame() {
  resize();
  controls.update();
  if (redrawWanted) {
    redrawWanted = false;
    framesDrawn += 1;
    renderer.render(scene, camera);
  }
  requestAnimationFrame(frame);
}

// For tests and scripts: where things are drawn.
window.viewer = {
  // the scene built, its meshes loaded and the robots posed
  ready: () => world.children.length > 0 && pendingMeshes === 0 && (links.size === 0 || posesReceived > 0),
  // what ready() waits on, to say which part of it did not come
  readiness: () => ({ sceneObjects: world.children.length, pendingMeshes, links: links.size, posesReceived,
    socket: socket ? ['connecting', 'open', 'closing', 'closed'][socket.readyState] : 'none' }),
  // the window pixel (x right, y down, CSS pixels) a world point is drawn at
  project: (x, y, z) => {
    // the camera as it is now: a follow moves it with the poses, its matrices are made at the next
    // frame (which a loaded machine draws late)
    camera.updateMatrixWorld();
    const p = new THREE.Vector3(x, y, z).project(camera);
    return [(p.x + 1) / 2 * canvas.clientWidth, (1 - p.y) / 2 * canvas.clientHeight];
  },
  // the pose (x y z qx qy qz qw) the page last placed a link at, from link_states
  linkPose: (name) => linkPoses.get(name) || null,
  lookAt: (eye, target) => {
    camera.position.set(eye[0], eye[1], eye[2]);
    controls.target.set(target[0], target[1], target[2]);
    controls.update();
    renderer.render(scene, camera);
  },
  time: () => simTime,
  framesDrawn: () => framesDrawn,
  // the frames of an image topic's overlay the page has shown
  overlayFrames: (topic) => overlayFrames.get(topic) || 0,
  // a scan or contacts overlay's points in the world, [[x, y, z], ...]
  overlayPointsInWorld: (topic) => {
    const drawn = overlayObjects.get(topic);
    if (!drawn) return [];
    const points = drawn.isPoints ? drawn : drawn.children[0];
    points.updateWorldMatrix(true, false);
    const p = points.geometry.getAttribute('position'), out = [];
    for (let k = 0; k < p.count; k++) {
      out.push(new THREE.Vector3(p.getX(k), p.getY(k), p.getZ(k)).applyMatrix4(points.matrixWorld).toArray());
    }
    return out;
  },
  // the last status from the viewer: {time, real_time_factor, paused}
  status: () => status,
};

// The buttons: gazebo_ros's services, called by the viewer node; step, the plant's step_physics.
for (const action of ['play', 'pause', 'reset_world', 'reset_simulation']) {
  document.getElementById(action).onclick = () => {
    if (socket && socket.readyState === WebSocket.OPEN) socket.send(JSON.stringify({ type: 'control', action }));
  };
}
document.getElementById('step').onclick = () => {
  const iterations = parseInt(document.getElementById('step_iterations').value, 10);
  if (socket && socket.readyState === WebSocket.OPEN && iterations > 0) {
    socket.send(JSON.stringify({ type: 'step', iterations }));
  }
};

// Keyboard driving with teleop.py's keys (its tables come from the viewer): a move key held sends
// its command every 100 ms; let go, the viewer stops the robot (the converter's dead man's rule).
let keys = { move: {}, scale: {} };
const drive = { speed: 1.0, turn: 0.5, held: null };
window.addEventListener('keydown', (event) => {
  if (event.target.tagName === 'SELECT' || event.target.type === 'number') return;  // typing in the step box
  const key = event.key.toLowerCase();
  if (keys.move[key]) drive.held = key;
  else if (keys.scale[key]) {
    drive.speed *= keys.scale[key][0];
    drive.turn *= keys.scale[key][1];
  } else if (key === ' ') drive.held = null;
  document.getElementById('drive_state').textContent =
    'speed ' + drive.speed.toFixed(2) + ', turn ' + drive.turn.toFixed(2) + (drive.held ? ' (' + drive.held + ')' : '');
});
window.addEventListener('keyup', (event) => {
  if (event.key.toLowerCase() === drive.held) drive.held = null;
});
setInterval(() => {
  const topic = document.getElementById('drive_topic').value;
  if (!drive.held || !topic || !socket || socket.readyState !== WebSocket.OPEN) return;
  const [ahead, turning] = keys.move[drive.held];
  socket.send(JSON.stringify({ type: 'drive', topic, speed: ahead * drive.speed, turn: turning * drive.turn }));
}, 100);

// Leaving says so at once: the viewer then stops what it fetched for this page.
let leaving = false;
window.addEventListener('pagehide', () => {
  leaving = true;
  if (socket) socket.close();
});

connect();
frame();
