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
  // A number the script computed (`-9.0e-1`) as the page's language writes it: its decimal
  // sign (window.LIGHTLAB_DECIMAL, from the crate's Lang::decimal_comma) and its minus sign
  // where a hyphen is a number's sign (window.LIGHTLAB_NUMBERS: the sign and the characters
  // it follows, from Lang::minus_sign and SIGN_FOLLOWS), as the crate's Lang::numbers_in.
  function number(s) {
    var out = String(s);
    var sign = window.LIGHTLAB_DECIMAL;
    if (sign && sign !== '.') out = out.replace(/(\d)\.(\d)/g, '$1' + sign + '$2');
    var facts = window.LIGHTLAB_NUMBERS;
    if (!facts || facts.minus === '-') return out;
    var c = out.split('');
    for (var i = 0; i < c.length; i++) {
      var signs = c[i] === '-' && /[0-9]/.test(c[i + 1] || '') && (i === 0 || facts.sign_follows.indexOf(c[i - 1]) >= 0);
      if (signs) c[i] = facts.minus;
    }
    return c.join('');
  }
  // A list of computed numbers, each to `digits` decimals, joined by the language's list
  // separator (window.LIGHTLAB_NUMBERS.list, from Lang::list_separator: `1.00, 0.50` in
  // English, `1,00 ; 0,50` in French, `1,00; 0,50` in Ukrainian).
  function numbers(values, digits) {
    var facts = window.LIGHTLAB_NUMBERS;
    return values.map(function (x) { return number(Number(x).toFixed(digits)); }).join(facts ? facts.list : ', ');
  }
  window.lightlabText = { T: T, TF: TF, fill: fill, number: number, numbers: numbers };
})();
