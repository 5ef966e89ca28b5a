// The script a module Web Worker runs (started by web/worker.browser.js).
import * as api from './index.browser.js';
import { createHost } from './worker-host.js';

const onMessage = createHost(api, (message, transfer) => self.postMessage(message, transfer));
self.addEventListener('message', (event) => onMessage(event.data));
