// Inline formulas wider than their line get a scrolling box of their own (reader.css):
// MathJax 3 does not line-break inline math. Marked once MathJax has typeset the page, and
// again when the window changes width.
(function () {
  "use strict";
  function mark() {
    document.querySelectorAll('mjx-container:not([display="true"])').forEach(function (math) {
      math.classList.remove("ep-wide-inline");
      var line = math.closest("p, li, dd, td, th, div, section") || document.body;
      if (math.getBoundingClientRect().width > line.clientWidth) {
        math.classList.add("ep-wide-inline");
      }
    });
  }
  window.addEventListener("load", function () {
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) {
      MathJax.startup.promise.then(mark);
    }
  });
  window.addEventListener("resize", mark);
})();

// The language switch (_templates/language-switch.html) goes to the same place of the same
// page: the anchor in the address, or the section being read, whose id is the same in every
// edition.
(function () {
  "use strict";
  document.addEventListener("click", function (event) {
    var link = event.target.closest && event.target.closest("a.language-switch__link");
    if (link && window.location.hash) {
      link.href = link.href.split("#")[0] + window.location.hash;
    }
  });
})();
