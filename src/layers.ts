/**
 * The source folders by role, lowest first: a module imports from its own folder or from the
 * folders of lower layers only (tests/unit/architecture.test.ts holds every import to it). Folders
 * of one layer know nothing of each other. docs/architecture.md draws the same order.
 */
export const SOURCE_LAYERS: readonly (readonly string[])[] = [
  ['input'], // checks of input at every entry point: the ParameterError, allowed ranges, decimal text
  ['physics', 'i18n', 'threads'], // the float64 reference and its data: no DOM, no three.js; the texts of every language; Web Worker requests
  ['fields', 'methods', 'environments'], // the registries: the film's thickness over the bubble (fields.ts), the ways to compute its colour (methods.ts), the light around it (environments.ts)
  ['settings'], // the schema of every user-facing parameter, the film's quality knobs, and the facts a frame and a material share (the method drawn, the pixel-ratio cap)
  ['gpu'], // three.js plumbing: shader source, defines, shared resources, the fullscreen pass
  ['film', 'gpuFilmDynamics'], // the film's colour on the GPU; the flowing film's dynamics on the GPU (physics/filmDynamics/ is its float64 twin)
  ['bubbleMaterials'], // the bubble's and the environment's materials
  ['meshMaterial', 'bubbleTwins'], // the material for any three.js mesh; the CPU twins of the bubble's shaders
  ['nodeMaterial'], // the material for three.js's WebGPURenderer: the film in TSL, its lighting model
  ['view'], // what is drawn for what is asked (the frame), and the bubble's view that draws it: renderer, probe
  ['plots'], // the plots of the film at the probe
  ['app', 'diagram'], // the demo's app: panel, settings in the URL, messages; the SVG diagram of the reflected beams
  ['element', 'pages', 'packageEntries', 'cli'], // entries: the custom element, the pages, the package's library entries (physics, material), the command line
];
