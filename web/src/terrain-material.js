// One material for every terrain tile: three's MeshStandardMaterial (lighting, fog, tone mapping)
// with its base colour replaced by a ramp on the world-space height, patched in with
// onBeforeCompile so that the tiles need no vertex colours or textures.
import * as THREE from 'three';

// Colours from sea floor to snow, by height relative to the world's highest point (sRGB,
// converted to linear in the shader since three lights in linear space).
const RAMP = /* glsl */ `
vec3 heightColour(float h) {
  vec3 c = mix(vec3(0.62, 0.58, 0.45), vec3(0.82, 0.77, 0.55), smoothstep(-0.1, 0.0, h)); // sea floor, beach
  c = mix(c, vec3(0.40, 0.60, 0.28), smoothstep(0.005, 0.04, h));  // lowland grass
  c = mix(c, vec3(0.25, 0.42, 0.20), smoothstep(0.08, 0.30, h));   // forest
  c = mix(c, vec3(0.50, 0.42, 0.32), smoothstep(0.35, 0.60, h));   // bare soil
  c = mix(c, vec3(0.58, 0.57, 0.55), smoothstep(0.60, 0.80, h));   // rock
  c = mix(c, vec3(0.96, 0.96, 0.98), smoothstep(0.86, 0.95, h));   // snow
  return pow(c, vec3(2.2));
}
`;

export function createTerrainMaterial() {
  const uniforms = { uMaxHeight: { value: 1000 } };
  const material = new THREE.MeshStandardMaterial({ roughness: 0.95, metalness: 0 });
  material.onBeforeCompile = (shader) => {
    Object.assign(shader.uniforms, uniforms);
    shader.vertexShader = `varying float vHeight;\n${shader.vertexShader}`.replace(
      '#include <begin_vertex>',
      '#include <begin_vertex>\nvHeight = (modelMatrix * vec4(transformed, 1.0)).y;');
    shader.fragmentShader = `uniform float uMaxHeight;\nvarying float vHeight;\n${RAMP}\n${shader.fragmentShader}`.replace(
      '#include <color_fragment>',
      '#include <color_fragment>\ndiffuseColor.rgb = heightColour(vHeight / uMaxHeight);');
  };
  return {
    material,
    /** The height, in metres, that the top of the ramp (snow) is given to. */
    setMaxHeight(metres) { uniforms.uMaxHeight.value = Math.max(1, metres); },
  };
}
