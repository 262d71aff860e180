/** mulberry32 (src/physics/seededRandom.ts): a test checks the same cases every run and a failure can be replayed. */
export { mulberry32 } from '../src/physics/seededRandom.ts';
