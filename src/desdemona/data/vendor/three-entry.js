// The parts of three.js the result view uses, bundled into one script that sets window.THREE.
export {
  AmbientLight, ArrowHelper, BoxGeometry, BufferGeometry, Color, CylinderGeometry, DirectionalLight,
  Float32BufferAttribute, GridHelper, Group, Line, LineBasicMaterial, LineDashedMaterial, Mesh,
  MeshBasicMaterial, MeshLambertMaterial, MeshPhongMaterial, MeshStandardMaterial, PerspectiveCamera,
  Quaternion, RingGeometry, Scene, SphereGeometry, TorusGeometry, Vector3, WebGLRenderer, Matrix4,
  Euler, AxesHelper, Object3D, DoubleSide
} from 'three';
export { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
