// The threaded build on 4 threads: see support/threads-suite.js.
import { threadsSuite } from './support/threads-suite.js';

threadsSuite(4);
