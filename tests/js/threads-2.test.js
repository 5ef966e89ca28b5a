// The threaded build on 2 threads: see support/threads-suite.js.
import { threadsSuite } from './support/threads-suite.js';

threadsSuite(2);
