// The script a Node worker_threads Worker runs (started by web/worker.node.js).
import { parentPort } from 'node:worker_threads';
import * as api from './index.node.js';
import { createHost } from './worker-host.js';

const onMessage = createHost(api, (message, transfer) => parentPort.postMessage(message, transfer));
parentPort.on('message', onMessage);
