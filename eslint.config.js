// ESLint flat config: the recommended rules for every JS file of the package, the demo, the
// benchmarks, the scripts and the tests, plus the repo's 100-column limit.
import js from '@eslint/js';
import globals from 'globals';

export default [
  {
    ignores: ['node_modules/', 'build*/', 'web/dist/', 'demo/dist/', 'test-output/', '.cache/'],
  },
  js.configs.recommended,
  {
    files: ['**/*.js', '**/*.mjs'],
    languageOptions: {
      ecmaVersion: 2024,
      sourceType: 'module',
      globals: { ...globals.node, ...globals.browser },
    },
    rules: {
      'max-len': ['error', { code: 100, ignoreUrls: true, ignoreRegExpLiterals: true }],
      'no-unused-vars': ['error', { argsIgnorePattern: '^_', caughtErrors: 'none' }],
      eqeqeq: ['error', 'smart'],
      'prefer-const': 'error',
      'no-var': 'error',
    },
  },
  {
    // Emscripten JS libraries: a script the link pastes into the glue, whose names it uses.
    files: ['bindings/*.js'],
    languageOptions: {
      sourceType: 'script',
      globals: { mergeInto: 'readonly', LibraryManager: 'readonly',
        emscripten_realloc_buffer: 'readonly' },
    },
  },
];
