import * as peers from './peers.js';
import { countryArcs, countryRings, indexedGraph } from './datasets.js';
const t = peers.triangleInWorker();
const g = indexedGraph(countryRings('110m').polylines);
const a = indexedGraph(countryArcs('110m').polylines);
try { console.log(await t.run(g)); } catch (e) { console.log('failed', e.message); }
console.log('arcs', a.xy.length/2, a.edges.length);
let t0 = performance.now();
try { console.log(peers.cdt(a)); } catch (e) { console.log('failed', e.message); }
console.log('cdt', performance.now()-t0);
try { console.log(peers.constrainautor(a)); } catch (e) { console.log('failed', e.message); }
try { console.log(await t.run(a)); } catch (e) { console.log('failed', e.message); }
t.close();
