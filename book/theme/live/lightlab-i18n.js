// lightlab's page words in the reader's language. A translated page loads
// generated/<lang>/live/texts.js first, which sets window.LIGHTLAB_TEXTS to
// {english: translation}, made by the crate from po/<lang>.po (src/live/texts.rs); an English
// page has no dictionary and shows the English. Every word the scripts show goes through
//   T(english)                   the translation, or the English itself
//   TF('{} of {} cases', [a, b]) the translation with each {} filled in order
//   number('9.0e-1')             a computed number with the language's decimal sign
// and the crate finds these literals to put them in the translation template, so a word is
// marked here and translated in the PO files, never typed twice.
(function () {
  'use strict';
  function T(english) {
    var d = window.LIGHTLAB_TEXTS;
    if (!d || typeof english !== 'string') return english;
    return Object.prototype.hasOwnProperty.call(d, english) ? d[english] : english;
  }
  function fill(template, args) {
    var parts = String(template).split('{}');
    var s = parts[0];
    for (var k = 1; k < parts.length; k++) s += (args[k - 1] === undefined ? '{}' : String(args[k - 1])) + parts[k];
    return s;
  }
  function TF(english, args) { return fill(T(english), args || []); }
  // A number the script computed (`9.0e-1`) with the page language's decimal sign, which
  // texts.js gives (window.LIGHTLAB_DECIMAL, from the crate's Lang::decimal_comma).
  function number(s) {
    var sign = window.LIGHTLAB_DECIMAL;
    return sign && sign !== '.' ? String(s).replace(/(\d)\.(\d)/g, '$1' + sign + '$2') : String(s);
  }
  // A list of computed numbers, each to `digits` decimals: `1.00, 0.50` in English, and
  // `1,00; 0,50` where the decimal sign is a comma (a comma between them would be ambiguous),
  // as the crate writes its own lists of numbers in those languages.
  function numbers(values, digits) {
    var comma = window.LIGHTLAB_DECIMAL && window.LIGHTLAB_DECIMAL !== '.';
    return values.map(function (x) { return number(Number(x).toFixed(digits)); }).join(comma ? '; ' : ', ');
  }
  window.lightlabText = { T: T, TF: TF, fill: fill, number: number, numbers: numbers };
})();
