/**
 * A node that passes its input through and calls `refresh` with the frame (its renderer, object,
 * camera, scene and material) before each render that draws it: the film's per-frame work (its
 * uniforms, textures and table brought up to the material), which WebGPURenderer runs as a node's
 * updateBefore (it calls no material's onBeforeRender).
 */
import { Node, type NodeFrame, NodeUpdateType } from 'three/webgpu';

export class FilmUpdateNode extends Node {
  constructor(
    private readonly input: Node,
    private readonly refresh: (frame: NodeFrame) => void,
  ) {
    super('vec3');
    this.updateBeforeType = NodeUpdateType.RENDER;
  }

  override setup(): Node {
    return this.input;
  }

  override updateBefore(frame: NodeFrame): boolean {
    if (frame.renderer) this.refresh(frame);
    return true;
  }
}
