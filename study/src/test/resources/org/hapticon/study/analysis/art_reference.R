# The aligned rank transform ANOVA and ART-C contrasts reproduced with base R only (no ARTool, no emmeans), as the
# reference AlignedRankTransformOracleTest checks the Kotlin implementation against.
#
#   Rscript art_reference.R DATA.csv FACTORS [CONTRAST_FACTORS]
#
# DATA.csv: columns subject, the factors (names as in FACTORS, comma-separated) and value. Levels keep their
# first-seen order. Prints one line per effect, "ANOVA,effect,F,df,dfError,p", then per contrast factor one line per
# pair of levels, "CONTRAST,factor,a,b,estimate,se,df,t,p" (p Tukey-adjusted), numbers with 17 significant digits.
#
# ART (Wobbrock et al., CHI 2011; ARTool's art() and anova() for y ~ A*B + Error(subject)): for each effect the
# response is aligned (y - full cell mean + the effect's estimated effect), rounded to 8 digits and ranked; aov() with
# subject as the error stratum gives the effect's F in the within-subject stratum. ART-C (Elkin et al., UIST 2021;
# ARTool's art.con(m, "A") for one factor): the ranks aligned for A, a linear model with subject as a factor, and the
# pairwise differences of A's estimated marginal means (the model's predictions on the full grid of subjects and
# cells, averaged with equal weights, as emmeans builds them) with their standard errors from vcov().
args <- commandArgs(trailingOnly = TRUE)
d <- read.csv(args[1], colClasses = "character")
factors <- strsplit(args[2], ",")[[1]]
contrast_factors <- if (length(args) >= 3) strsplit(args[3], ",")[[1]] else character(0)
d$value <- as.numeric(d$value)
d$subject <- factor(d$subject, levels = unique(d$subject))
for (f in factors) d[[f]] <- factor(d[[f]], levels = unique(d[[f]]))
options(contrasts = c("contr.sum", "contr.poly"))

rhs <- paste(factors, collapse = "*")
terms_in_order <- attr(terms(as.formula(paste("value ~", rhs))), "term.labels")

cell_mean <- function(vars) {
  if (length(vars) == 0) return(rep(mean(d$value), nrow(d)))
  ave(d$value, interaction(d[vars], drop = TRUE), FUN = mean)
}

aligned_ranks <- function(term) {
  vars <- strsplit(term, ":")[[1]]
  k <- length(vars)
  effect <- 0
  for (size in 0:k) {
    subsets <- if (size == 0) list(character(0)) else combn(vars, size, simplify = FALSE)
    for (s in subsets) effect <- effect + (-1)^(k - size) * cell_mean(s)
  }
  rank(round(d$value - cell_mean(factors) + effect, 8))
}

for (term in terms_in_order) {
  d$r <- aligned_ranks(term)
  fit <- aov(as.formula(paste("r ~", rhs, "+ Error(subject)")), data = d)
  within <- summary(fit)[["Error: Within"]][[1]]
  rownames(within) <- trimws(rownames(within))
  cat(sprintf("ANOVA,%s,%.17g,%d,%d,%.17g\n", term, within[term, "F value"], as.integer(within[term, "Df"]),
              as.integer(within["Residuals", "Df"]), within[term, "Pr(>F)"]))
}

for (f in contrast_factors) {
  d$r <- aligned_ranks(f)
  fit <- lm(as.formula(paste("r ~ subject +", rhs)), data = d)
  grid <- expand.grid(c(list(subject = levels(d$subject)), lapply(setNames(factors, factors), function(x) levels(d[[x]]))))
  X <- model.matrix(delete.response(terms(fit)), grid, contrasts.arg = fit$contrasts, xlev = fit$xlevels)
  b <- coef(fit)
  V <- vcov(fit)
  lv <- levels(d[[f]])
  L <- t(sapply(lv, function(l) colMeans(X[grid[[f]] == l, , drop = FALSE])))
  k <- length(lv)
  for (i in 1:(k - 1)) for (j in (i + 1):k) {
    w <- L[i, ] - L[j, ]
    est <- sum(w * b)
    se <- sqrt(drop(t(w) %*% V %*% w))
    t <- est / se
    p <- ptukey(abs(t) * sqrt(2), k, fit$df.residual, lower.tail = FALSE)
    cat(sprintf("CONTRAST,%s,%s,%s,%.17g,%.17g,%d,%.17g,%.17g\n", f, lv[i], lv[j], est, se, as.integer(fit$df.residual), t, p))
  }
}
