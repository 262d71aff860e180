// Lint: ESLint's recommended rules and typescript-eslint's type-aware ones (they read tsconfig.json).
import js from '@eslint/js';
import tseslint from 'typescript-eslint';

export default tseslint.config(
  { ignores: ['dist/', 'dist-e2e/', 'dist-lib/', 'node_modules/', 'test-results/', 'playwright-report/'] },
  js.configs.recommended,
  ...tseslint.configs.recommendedTypeChecked,
  {
    languageOptions: { parserOptions: { projectService: true, tsconfigRootDir: import.meta.dirname } },
    rules: {
      // Messages and test titles print tuples (an RGB triple) with their default join.
      '@typescript-eslint/restrict-template-expressions': ['error', { allowNumber: true, allowArray: true }],
      // A leading underscore marks a deliberately unused binding (a destructured field left out).
      '@typescript-eslint/no-unused-vars': [
        'error',
        { argsIgnorePattern: '^_', varsIgnorePattern: '^_', destructuredArrayIgnorePattern: '^_' },
      ],
    },
  },
  {
    // Budgets for the code that ships and the tools (tests may keep longer files and callbacks;
    // docs/architecture.md#budgets). A file of at most 300 lines, every line counted as `wc -l`
    // counts them, is one topic a reader holds at once. A function of at most 60 lines, blank
    // lines and comments left out, fits one screen and does one thing: past 60, a function of
    // this tree holds several steps that each deserve a name of their own.
    files: ['src/**/*.ts', 'scripts/**/*.ts'],
    rules: {
      'max-lines': ['error', { max: 300, skipBlankLines: false, skipComments: false }],
      'max-lines-per-function': ['error', { max: 60, skipBlankLines: true, skipComments: true, IIFEs: true }],
    },
  },
  {
    // Data, not code: published tables and the message catalogues grow with their source.
    files: ['src/physics/data/**/*.ts', 'src/i18n/en.ts', 'src/i18n/ja.ts'],
    rules: { 'max-lines': 'off' },
  },
  { files: ['**/*.js'], ...tseslint.configs.disableTypeChecked },
);
