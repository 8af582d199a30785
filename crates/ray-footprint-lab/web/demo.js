// The demo: loads the crate's WGSL modules and render.wgsl, makes the ground texture's mip chain,
// and renders the scene into the canvas in the chosen mode. `demo.render(mode)` resolves to the
// WebGPU messages that arrived (Tint's warnings and errors, validation errors, the device's
// loss); a test drives it through the DevTools protocol.

"use strict";

// The modules the scene calls, in the order they go in front of render.wgsl.
const MODULES = ["ray_cone", "ray_diff", "wireframe"];
// The crate's shaders/wgsl/, from crates/ray-footprint-lab/web/.
const SHADERS = "../../../shaders/wgsl/";
// The mode numbers of render.wgsl.
const MODES = { mip0: 0, cone: 1, cone_anisotropic: 2, wireframe: 3 };
const TEXTURE_SIZE = 512;

const messages = [];

// The text at `url`; throws naming it when it is not there.
async function text(url) {
  const response = await fetch(url);
  if (!response.ok) {
    throw new Error(`${url}: ${response.status}`);
  }
  return response.text();
}

// The shader: the modules, then render.wgsl.
async function shaderSource() {
  const parts = await Promise.all([...MODULES.map((name) => text(`${SHADERS}${name}.wgsl`)), text("render.wgsl")]);
  return parts.join("\n");
}

// The shader module of `code`, its compiler's warnings and errors added to the messages.
async function compile(device, name, code) {
  const module = device.createShaderModule({ code });
  const info = await module.getCompilationInfo();
  info.messages
    .filter((message) => message.type !== "info")
    .forEach((message) => messages.push(`Tint ${message.type} in ${name} at line ${message.lineNum}:${message.linePos}: ${message.message}`));
  return module;
}

// A compute pipeline of `entryPoint`.
function pipeline(device, module, entryPoint) {
  return device.createComputePipeline({ layout: "auto", compute: { module, entryPoint } });
}

// Dispatches `pipeline` over `width` x `height` with `entries` bound.
function dispatch(device, encoder, pipeline, entries, width, height) {
  const pass = encoder.beginComputePass();
  pass.setPipeline(pipeline);
  pass.setBindGroup(0, device.createBindGroup({ layout: pipeline.getBindGroupLayout(0), entries }));
  pass.dispatchWorkgroups(Math.ceil(width / 8), Math.ceil(height / 8));
  pass.end();
}

// The ground texture with its full mip chain, made by render.wgsl's texture entry points.
function groundTexture(device, module) {
  const levels = Math.log2(TEXTURE_SIZE) + 1;
  const texture = device.createTexture({
    size: [TEXTURE_SIZE, TEXTURE_SIZE],
    mipLevelCount: levels,
    format: "rgba8unorm",
    usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.STORAGE_BINDING,
  });
  const level = (mip) => texture.createView({ baseMipLevel: mip, mipLevelCount: 1 });
  const encoder = device.createCommandEncoder();
  dispatch(device, encoder, pipeline(device, module, "texture_level0"), [{ binding: 4, resource: level(0) }], TEXTURE_SIZE, TEXTURE_SIZE);
  const downsample = pipeline(device, module, "texture_downsample");
  for (let mip = 1; mip < levels; mip++) {
    const size = TEXTURE_SIZE >> mip;
    const entries = [{ binding: 4, resource: level(mip) }, { binding: 5, resource: level(mip - 1) }];
    dispatch(device, encoder, downsample, entries, size, size);
  }
  device.queue.submit([encoder.finish()]);
  return texture;
}

// The device, the pipeline and the resources `render` needs.
async function start() {
  if (!navigator.gpu) {
    throw new Error("this browser has no WebGPU");
  }
  const adapter = await navigator.gpu.requestAdapter();
  if (!adapter) {
    throw new Error("WebGPU offers no adapter");
  }
  const device = await adapter.requestDevice();
  device.addEventListener("uncapturederror", (event) => messages.push(`uncaptured error: ${event.error.message}`));
  device.lost.then((info) => messages.push(`device lost (${info.reason}): ${info.message}`));
  const module = await compile(device, "the modules and render.wgsl", await shaderSource());
  const canvas = document.getElementById("image");
  // The scene goes into a storage texture, is read back and put on a 2D canvas: a WebGPU canvas
  // texture with storage usage is not offered everywhere, and headless Chromium on SwiftShader
  // loses the device when it presents a WebGPU canvas at all.
  const context = canvas.getContext("2d");
  const image = device.createTexture({
    size: [canvas.width, canvas.height],
    format: "rgba8unorm",
    usage: GPUTextureUsage.STORAGE_BINDING | GPUTextureUsage.COPY_SRC,
  });
  const bytesPerRow = Math.ceil((4 * canvas.width) / 256) * 256;
  const readback = device.createBuffer({ size: bytesPerRow * canvas.height, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
  const sampler = device.createSampler({
    addressModeU: "repeat",
    addressModeV: "repeat",
    magFilter: "linear",
    minFilter: "linear",
    mipmapFilter: "linear",
    maxAnisotropy: 16,
  });
  const params = device.createBuffer({ size: 16, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
  return { device, canvas, context, image, bytesPerRow, readback, params, sampler, texture: groundTexture(device, module), render: pipeline(device, module, "render") };
}

const ready = start();

// The last render asked for: each waits for the one before (they share the readback buffer).
let last = Promise.resolve();

// Renders `mode` into the canvas after any render asked for before; resolves, once it is shown,
// to every message since the page loaded.
function render(mode) {
  const next = last.catch(() => {}).then(() => draw(mode));
  last = next;
  return next;
}

// Renders `mode` into the canvas; resolves, once it is shown, to every message since the page loaded.
async function draw(mode) {
  const scene = await ready;
  if (!(mode in MODES)) {
    throw new Error(`no mode ${mode}; the modes are ${Object.keys(MODES).join(", ")}`);
  }
  const { device } = scene;
  device.queue.writeBuffer(scene.params, 0, new Uint32Array([MODES[mode], 0, 0, 0]));
  const entries = [
    { binding: 0, resource: { buffer: scene.params } },
    { binding: 1, resource: scene.texture.createView() },
    { binding: 2, resource: scene.sampler },
    { binding: 3, resource: scene.image.createView() },
  ];
  const encoder = device.createCommandEncoder();
  const [width, height] = [scene.canvas.width, scene.canvas.height];
  dispatch(device, encoder, scene.render, entries, width, height);
  encoder.copyTextureToBuffer({ texture: scene.image }, { buffer: scene.readback, bytesPerRow: scene.bytesPerRow }, [width, height]);
  device.queue.submit([encoder.finish()]);
  await scene.readback.mapAsync(GPUMapMode.READ);
  const rows = new Uint8Array(scene.readback.getMappedRange());
  const pixels = new ImageData(width, height);
  for (let y = 0; y < height; y++) {
    pixels.data.set(rows.subarray(y * scene.bytesPerRow, y * scene.bytesPerRow + 4 * width), 4 * width * y);
  }
  scene.readback.unmap();
  scene.context.putImageData(pixels, 0, 0);
  await new Promise((shown) => requestAnimationFrame(() => requestAnimationFrame(shown)));
  document.querySelectorAll("#modes button").forEach((button) => button.setAttribute("aria-pressed", String(button.dataset.mode === mode)));
  return [...messages];
}

// Shows `mode`, or what went wrong, under the canvas.
async function show(mode) {
  const status = document.getElementById("status");
  try {
    const problems = await render(mode);
    status.textContent = problems.join("\n");
  } catch (error) {
    status.textContent = String(error);
  }
}

document.querySelectorAll("#modes button").forEach((button) => button.addEventListener("click", () => show(button.dataset.mode)));
show("cone");

const demo = { render };
